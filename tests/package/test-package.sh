#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The .deb `make package` builds, as a user's computer gets it: built (CPack, dependencies from dpkg-shlibdeps),
# its metadata and file list read (dpkg-deb), lintian's verdict, then unpacked into a fresh root, where the
# installed programs run from their installed paths: toffee --version, toffee-cli --help, the window's
# --self-test, and toffee-cli importing a .tools archive through the zip reader module (and saying what to do
# when that module is gone). test-package.sh BUILD_DIR VERSION SOURCE_DIR
set -eu
build=$1
version=$2
source=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/toffee-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "package: $*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -B "$work/out" > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack failed"; }
deb=$(ls "$work"/out/toffee_*.deb)
[ "$(basename "$deb")" = "toffee_${version}_amd64.deb" ] || fail "the package is $(basename "$deb"), not version $version"

info=$(dpkg-deb --info "$deb")
echo "$info" | grep -q "^ Version: $version\$" || fail "dpkg-deb --info: no Version $version"
# Computed from the binaries by dpkg-shlibdeps: Qt's libraries with their versions, libc.
# The modules' too: Qt Charts for the chart, libzip for the zip reader.
for lib in "libqt6core6 (>=" "libqt6widgets6 (>=" "libqt6sql6 (>=" "libqt6serialport6 (>=" "libc6 (>=" \
    "libqt6charts6 (>=" "libzip4 (>="; do
    echo "$info" | grep "^ Depends:" | grep -qF "$lib" || fail "Depends lacks $lib"
done

files=$(dpkg-deb --contents "$deb")
for path in usr/bin/toffee usr/bin/toffee-cli usr/bin/toffee-emulator \
    usr/share/applications/org.toffee.Toffee.desktop usr/share/metainfo/org.toffee.Toffee.metainfo.xml \
    usr/share/icons/hicolor/scalable/apps/org.toffee.Toffee.svg \
    usr/share/icons/hicolor/48x48/apps/org.toffee.Toffee.png \
    usr/share/icons/hicolor/256x256/apps/org.toffee.Toffee.png \
    usr/share/man/man1/toffee.1.gz usr/share/man/man1/toffee-cli.1.gz usr/share/man/man1/toffee-emulator.1.gz \
    usr/share/bash-completion/completions/toffee-cli usr/share/doc/toffee/copyright \
    usr/share/doc/toffee/guide/GUIDE.md usr/share/doc/toffee/guide/screenshots/window-light.png \
    usr/lib/x86_64-linux-gnu/toffee/toffee_zipreader.so usr/lib/x86_64-linux-gnu/toffee/toffee_historychart.so; do
    echo "$files" | grep -q " \./$path\$" || fail "the package has no /$path"
done

if command -v lintian > /dev/null; then
    lintian --fail-on error,warning "$deb" 2>&1 | grep -v "running with root privileges" || true
    lintian --fail-on error,warning "$deb" > /dev/null 2>&1 || fail "lintian finds errors or warnings"
else
    fail "lintian is missing: make test installs it"
fi

root="$work/root"
dpkg-deb -x "$deb" "$root"
out=$("$root/usr/bin/toffee" --version)
[ "$out" = "Toffee $version" ] || fail "installed toffee --version says \"$out\""
"$root/usr/bin/toffee-cli" --help | grep -q "^usage: toffee-cli" || fail "installed toffee-cli --help"
[ "$("$root/usr/bin/toffee-cli" --version)" = "toffee-cli $version" ] || fail "installed toffee-cli --version"
HOME="$work/home" XDG_DATA_HOME="$work/home/data" XDG_CONFIG_HOME="$work/home/config" QT_QPA_PLATFORM=offscreen \
    "$root/usr/bin/toffee" --self-test > "$work/selftest.log" 2>&1 || { cat "$work/selftest.log"; fail "installed toffee --self-test failed"; }
grep -q "self-test passed" "$work/selftest.log" || fail "installed toffee --self-test did not pass"
# The zip reader is loaded from the installed lib/toffee when a .tools archive is read; without it, the reason.
tools="$source/tests/data/cam/two-tools.tools"
"$root/usr/bin/toffee-cli" import "$tools" --into "$work/imported.tbl" > "$work/import.log" 2>&1 || { cat "$work/import.log"; fail "installed toffee-cli import of a .tools archive failed"; }
grep -q "^T7 " "$work/imported.tbl" || fail "installed toffee-cli import wrote no T7"
rm "$root/usr/lib/x86_64-linux-gnu/toffee/toffee_zipreader.so"
if "$root/usr/bin/toffee-cli" import "$tools" --into "$work/again.tbl" > "$work/missing.log" 2>&1; then
    fail "toffee-cli imported a .tools archive without its zip reader"
fi
grep -q "zip reader .*toffee_zipreader.so is missing.*reinstall Toffee" "$work/missing.log" || { cat "$work/missing.log"; fail "no clear message when the zip reader is missing"; }
[ ! -e "$work/again.tbl" ] || fail "a failed import wrote a table"
man -l "$root/usr/share/man/man1/toffee-cli.1.gz" > /dev/null 2>&1 || zcat "$root/usr/share/man/man1/toffee-cli.1.gz" | grep -q "^.TH TOFFEE" || fail "the manual page does not read"
echo "package: $(basename "$deb") builds, passes lintian, and its installed programs run"
