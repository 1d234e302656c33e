// SPDX-License-Identifier: GPL-3.0-or-later
// Start-up, side by side: Toffee's window against a bare Qt 6 QMainWindow of the same size
// (toffee-bench-barewindow), started in turn on the same X display, and the bare window with one label (the
// floor of any window that draws text). A run's time is from fork() to the X server's MapNotify of the
// program's first top-level window, read by this process from the server itself; its peak is the process's
// VmHWM once the program has settled after the map (deferred start-up work included), before it is stopped.
//   toffee-bench-startup [--runs N] [--settle MS] [--verbose] [-- TOFFEE_ARGS...]
// Needs an X display (make bench starts Xvfb when there is none). Each program gets fresh, empty settings,
// data and cache folders, so neither reads what the person running the benchmark has.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <xcb/xcb.h>

namespace {

using Clock = std::chrono::steady_clock;

struct Run
{
    double mapMs = 0;
    double peakMb = 0;
};

struct Settings
{
    int runs = 9;
    int settleMs = 1500;
    bool verbose = false;
    std::vector<std::string> toffeeArgs;
};

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// VmHWM, the resident set's high-water mark, in MB (kB / 1024).
double peakMb(pid_t pid)
{
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0)
            return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
    }
    return -1;
}

// Waits for the first MapNotify of a top-level window that is not override-redirect (a tooltip or a popup
// is). Without a window manager every top-level window is the root's child, whose map the root's
// SubstructureNotify reports.
std::optional<Clock::time_point> waitForMap(xcb_connection_t *x, pid_t child)
{
    const auto deadline = Clock::now() + std::chrono::seconds(20);
    pollfd fd { xcb_get_file_descriptor(x), POLLIN, 0 };
    while (Clock::now() < deadline) {
        while (xcb_generic_event_t *event = xcb_poll_for_event(x)) {
            const bool mapped = (event->response_type & 0x7f) == XCB_MAP_NOTIFY
                && !reinterpret_cast<xcb_map_notify_event_t *>(event)->override_redirect;
            std::free(event);
            if (mapped)
                return Clock::now();
        }
        if (xcb_connection_has_error(x))
            return std::nullopt;
        int status = 0;
        if (waitpid(child, &status, WNOHANG) == child)
            return std::nullopt; // it ended without a window
        poll(&fd, 1, 50);
    }
    return std::nullopt;
}

void drain(xcb_connection_t *x)
{
    xcb_flush(x);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    while (xcb_generic_event_t *event = xcb_poll_for_event(x))
        std::free(event);
}

std::optional<Run> runOnce(xcb_connection_t *x, const std::vector<std::string> &argv, int settleMs)
{
    drain(x);
    std::vector<char *> args;
    for (const std::string &a : argv)
        args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);
    const auto started = Clock::now();
    const pid_t child = fork();
    if (child == 0) {
        execv(args[0], args.data());
        std::fprintf(stderr, "toffee-bench-startup: cannot run %s: %s\n", args[0], std::strerror(errno));
        _exit(127);
    }
    if (child < 0)
        return std::nullopt;
    const auto mapped = waitForMap(x, child);
    std::optional<Run> run;
    if (mapped) {
        std::this_thread::sleep_for(std::chrono::milliseconds(settleMs));
        run = Run { std::chrono::duration<double, std::milli>(*mapped - started).count(), peakMb(child) };
    }
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    if (!mapped)
        std::fprintf(stderr, "toffee-bench-startup: %s mapped no window\n", args[0]);
    return run;
}

std::string binDir(const char *self)
{
    const std::string path(self);
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

// Fresh settings, data and cache folders for both programs: a first start, the same for each run.
bool useFreshFolders(std::string &top)
{
    char pattern[] = "/tmp/toffee-bench-startup-XXXXXX";
    if (!mkdtemp(pattern))
        return false;
    top = pattern;
    setenv("XDG_CONFIG_HOME", (top + "/config").c_str(), 1);
    setenv("XDG_DATA_HOME", (top + "/data").c_str(), 1);
    setenv("XDG_CACHE_HOME", (top + "/cache").c_str(), 1);
    setenv("XDG_RUNTIME_DIR", (top + "/runtime").c_str(), 1);
    setenv("QT_QPA_PLATFORM", "xcb", 1);
    std::filesystem::create_directory(top + "/runtime");
    std::filesystem::permissions(top + "/runtime", std::filesystem::perms::owner_all);
    return true;
}

Settings parse(int argc, char *argv[])
{
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a(argv[i]);
        if (a == "--runs" && i + 1 < argc)
            s.runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--settle" && i + 1 < argc)
            s.settleMs = std::max(0, std::atoi(argv[++i]));
        else if (a == "--verbose")
            s.verbose = true;
        else if (a == "--") {
            s.toffeeArgs.assign(argv + i + 1, argv + argc);
            break;
        }
    }
    return s;
}

// The three programs' figures, side by side; the ratio is taken run by run (each toffee run against the bare
// run just before it), and its median told.
void report(const Settings &s, const std::vector<Run> &bare, const std::vector<Run> &label,
    const std::vector<Run> &toffee)
{
    std::vector<double> ratios;
    for (size_t i = 0; i < bare.size(); ++i)
        ratios.push_back(toffee[i].mapMs / bare[i].mapMs);
    const auto ms = [](const std::vector<Run> &runs) {
        std::vector<double> v;
        for (const Run &r : runs)
            v.push_back(r.mapMs);
        return median(v);
    };
    const auto mb = [](const std::vector<Run> &runs) {
        std::vector<double> v;
        for (const Run &r : runs)
            v.push_back(r.peakMb);
        return median(v);
    };
    std::printf(
        "start-up to the X server's map, %d alternating runs (medians): toffee %.1f ms, bare QMainWindow "
        "%.1f ms; ratio %.2fx (median of the %d paired ratios); the bare window with one label %.1f ms\n",
        s.runs, ms(toffee), ms(bare), median(ratios), s.runs, ms(label));
    std::printf(
        "peak memory (VmHWM, %d ms after the map; medians): toffee %.1f MB, bare QMainWindow %.1f MB; "
        "the bare window with one label %.1f MB\n",
        s.settleMs, mb(toffee), mb(bare), mb(label));
}

} // namespace

int main(int argc, char *argv[])
{
    const Settings settings = parse(argc, argv);
    int screenNumber = 0;
    xcb_connection_t *x = xcb_connect(nullptr, &screenNumber);
    if (xcb_connection_has_error(x)) {
        std::fprintf(stderr,
            "toffee-bench-startup: no X display (DISPLAY is not set or not reachable); run it "
            "under xvfb-run -a, as make bench does.\n");
        return 2;
    }
    xcb_screen_iterator_t screens = xcb_setup_roots_iterator(xcb_get_setup(x));
    for (int i = 0; i < screenNumber; ++i)
        xcb_screen_next(&screens);
    const uint32_t mask = XCB_EVENT_MASK_SUBSTRUCTURE_NOTIFY;
    xcb_change_window_attributes(x, screens.data->root, XCB_CW_EVENT_MASK, &mask);
    xcb_flush(x);

    std::string folders;
    if (!useFreshFolders(folders))
        return 2;
    const std::string dir = binDir(argv[0]);
    std::vector<std::string> bareArgs { dir + "/toffee-bench-barewindow" };
    std::vector<std::string> labelArgs { dir + "/toffee-bench-barewindow", "--label" };
    std::vector<std::string> toffeeArgs { dir + "/toffee" };
    toffeeArgs.insert(toffeeArgs.end(), settings.toffeeArgs.begin(), settings.toffeeArgs.end());

    // One start of each first, not counted: the libraries, fonts and plugins come into the page cache.
    if (!runOnce(x, bareArgs, 200) || !runOnce(x, labelArgs, 200) || !runOnce(x, toffeeArgs, 200))
        return 1;
    std::vector<Run> bare, label, toffee;
    for (int i = 0; i < settings.runs; ++i) {
        const auto b = runOnce(x, bareArgs, settings.settleMs);
        const auto t = runOnce(x, toffeeArgs, settings.settleMs);
        const auto l = runOnce(x, labelArgs, settings.settleMs);
        if (!b || !t || !l)
            return 1;
        bare.push_back(*b);
        label.push_back(*l);
        toffee.push_back(*t);
        if (settings.verbose)
            std::printf("run %d: bare %.1f ms %.1f MB, toffee %.1f ms %.1f MB\n", i + 1, b->mapMs, b->peakMb,
                t->mapMs, t->peakMb);
    }
    report(settings, bare, label, toffee);
    xcb_disconnect(x);
    std::error_code ignored;
    std::filesystem::remove_all(folders, ignored);
    return 0;
}
