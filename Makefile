# Toffee — the two commands of the README, and a few more for developers.
#   make run    install what is missing, build, open the window (on the emulator)
#   make test   install what is missing, build, run the whole suite headless
# Builds go to build/ with Ninja; a second `make` rebuilds only what changed.

BUILD_DIR := build
PRESET    := default

# The Debian packages the build, the tests and `make run` need (bookworm; Qt 6.4.2). On the last two lines: the
# shared library's driver and the throwaway server the suite starts for itself (tests/support/pgcluster.h), the
# validators of the desktop entry, the AppStream metainfo and the package, and what the real controllers the
# suite tests against need (the Carvera firmware's simulator: protobuf; grblHAL on a pty: socat).
DEB_PACKAGES := cmake ninja-build g++ make \
	qt6-base-dev qt6-base-dev-tools qt6-qpa-plugins qt6-serialport-dev qt6-charts-dev libqt6opengl6-dev \
	qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools \
	libqt6svg6 libqt6sql6-sqlite libgl-dev fonts-dejavu-core fonts-wqy-microhei xvfb xauth qt6-translations-l10n \
	pkg-config libzip-dev libxcb1-dev \
	postgresql libqt6sql6-psql \
	desktop-file-utils appstream lintian \
	libprotobuf32 socat

# `make bench` also runs LinuxCNC's own interpreter (rs274) on the job check's program, as its yardstick.
BENCH_PACKAGES := linuxcnc-uspace

# The suite's tests against LinuxCNC itself (../shared/peers/linuxcnc) run Debian's LinuxCNC: .ci/run installs it
# (`make peer-deps`) when the peer is there; without it those tests skip and say so.
PEER_PACKAGES := linuxcnc-uspace

# `make fuzz` also needs clang and its libFuzzer and sanitizer runtimes.
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_SECONDS ?= 600

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps peer-deps configure build run test test-calendar screenshots bench fuzz format clean package

all: build

# Installs whichever of the Debian packages named in $(1) are missing.
define install_missing
	@missing=""; \
	for p in $(1); do \
		dpkg-query -W -f='$${Status}\n' "$$p" 2>/dev/null | grep -q '^install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
		echo "toffee: installing Debian packages:$$missing"; \
		$(SUDO) apt-get update -qq && \
		$(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call install_missing,$(DEB_PACKAGES))

peer-deps:
	$(call install_missing,$(PEER_PACKAGES))

$(BUILD_DIR)/build.ninja: | deps
	cmake --preset $(PRESET)

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build --preset $(PRESET)

# With no display (a server, a container) the window opens on a virtual X display instead of failing.
run: build
	@if [ -n "$$DISPLAY$$WAYLAND_DISPLAY" ]; then \
		$(BUILD_DIR)/bin/toffee --emulator resources/examples/example.json; \
	else \
		echo "toffee: no display found; opening the window on a virtual X display (xvfb-run). Ctrl-C quits."; \
		xvfb-run -a $(BUILD_DIR)/bin/toffee --emulator resources/examples/example.json; \
	fi

test: build
	ctest --preset $(PRESET) --output-on-failure

# The screenshots in docs/ (the README's and the user's guide's), taken again by the suite's window stories as they
# run, offscreen, into docs/screenshots/ (the stories on the real controllers take theirs when the peers are set).
screenshots: build
	TOFFEE_SCREENSHOTS=$(CURDIR)/docs/screenshots ctest --preset $(PRESET) --output-on-failure \
		-R '^tst_(mainwindow|guidetour|machinistday|wifiwindow|toolcontextmenu|carverafirmwarewindow|grblhalwindow|linuxcncwindow)$$'

# The whole suite again with the calendar moved (Debian's libfaketime): two years ahead, and in 2039, past the
# end of 32-bit seconds. Nothing it checks may depend on the day: the product reads the time through one seam
# (model/clock.h) that the tests set. Monotonic clocks, which every time limit uses, are left alone, and the
# PostgreSQL server the suite starts keeps the real clock (with its clock moved its lock timeouts never fire).
CALENDAR_PACKAGES := faketime libfaketime
test-calendar: build
	$(call install_missing,$(CALENDAR_PACKAGES))
	@lib=$$(dpkg -L libfaketime | grep "/libfaketime.so.1$$"); \
	for when in "+2y" "@2039-03-14 09:26:53"; do \
		echo "toffee: the whole suite with the calendar at $$when"; \
		LD_PRELOAD=$$lib FAKETIME="$$when" FAKETIME_DONT_FAKE_MONOTONIC=1 \
			FAKETIME_SKIP_CMDS=postgres,initdb,pg_ctl,pg_ctlcluster,rtapi_app,milltask,linuxcncsvr,linuxcncrsh,halcmd,io \
			ctest --preset $(PRESET) --output-on-failure || exit 1; \
	done

# A .deb of the installed layout (CPack; its dependencies from dpkg-shlibdeps), in build/.
package: build
	cd $(BUILD_DIR) && cpack

bench: build
	$(call install_missing,$(BENCH_PACKAGES))
	@for i in 1 2 3 4 5; do \
		QT_QPA_PLATFORM=offscreen $(BUILD_DIR)/bin/toffee --lang en --self-test 2>/dev/null \
			| sed -n 's/.*first frame after \([0-9]*\) ms.*/\1/p'; \
	done | sort -n | awk '{ t[NR] = $$1 } END { print "window to first frame (toffee --self-test, offscreen), median of 5: " t[3] " ms" }'
	@# Start-up beside a bare Qt 6 window of the same size, on a display of its own (issue 16).
	xvfb-run -a -s "-screen 0 1920x1080x24" $(BUILD_DIR)/bin/toffee-bench-startup --runs 9
	$(BUILD_DIR)/bin/toffee-bench-table
	$(BUILD_DIR)/bin/toffee-bench-interpreter 1000000
	$(BUILD_DIR)/bin/toffee-bench-library 1000000
	$(BUILD_DIR)/bin/toffee-bench-sharedlibrary
	QT_QPA_PLATFORM=offscreen $(BUILD_DIR)/bin/toffee-bench-historychart 10000
	$(BUILD_DIR)/bin/toffee-bench-jobcheck 5000000
	$(BUILD_DIR)/bin/toffee-bench-camimport
	$(BUILD_DIR)/bin/toffee-bench-wire
	TOFFEE_GRBLHAL_PEER=$${TOFFEE_GRBLHAL_PEER:-$(wildcard $(CURDIR)/../shared/peers/grblhal/start)} \
		$(BUILD_DIR)/bin/toffee-bench-grblhal-probe
	TOFFEE_LINUXCNC_PEER=$${TOFFEE_LINUXCNC_PEER:-$(wildcard $(CURDIR)/../shared/peers/linuxcnc/start)} \
		$(BUILD_DIR)/bin/toffee-bench-linuxcnc-probe
	$(BUILD_DIR)/bin/toffee-cli --emulator link-test --count 10000
	@link=$$(mktemp -u /tmp/toffee-bench-tty.XXXXXX); \
	$(BUILD_DIR)/bin/toffee-emulator --link $$link > /dev/null & pid=$$!; \
	for i in 1 2 3 4 5 6 7 8 9 10; do [ -e $$link ] && break; sleep 0.2; done; \
	$(BUILD_DIR)/bin/toffee-cli --port $$link link-test --count 10000; status=$$?; \
	kill $$pid; exit $$status

# Each fuzz target for FUZZ_SECONDS (600 by default), two at a time: `make fuzz FUZZ_SECONDS=60` for a quick look.
fuzz:
	$(call install_missing,$(DEB_PACKAGES) $(FUZZ_PACKAGES))
	@[ -f build-fuzz/build.ninja ] || cmake --preset fuzz
	cmake --build --preset fuzz
	tests/fuzz/run-fuzzers.sh $(FUZZ_SECONDS)

format:
	git ls-files '*.cpp' '*.h' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR)
