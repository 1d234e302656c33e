#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Stops and removes the throwaway PostgreSQL clusters (tests/support/pgcluster.cpp) whose test process is
# gone, then their common root if nothing else is in it. ctest runs this before the tests that need a server
# (pgcluster_setup: what a killed run left) and after them (pgcluster_cleanup: a test binary that crashed
# never ran its destructor). A cluster whose test is still running, under a ctest run alongside, is left alone.

root="${TMPDIR:-/tmp}"
root="${root%/}/toffee-pgtest"

# True while the process named in the cluster's owner file (pid and start time) is alive.
owner_alive() {
    if ! { read -r pid start < "$1/owner"; } 2>/dev/null; then
        # No owner file yet: a cluster being made this instant, unless the folder is older than a minute.
        [ -n "$(find "$1" -maxdepth 0 -mmin -1 2>/dev/null)" ]
        return
    fi
    stat=$(cat "/proc/$pid/stat" 2>/dev/null) || return 1
    # Fields after the name, which may hold spaces: state, then 19 more up to the start time.
    # shellcheck disable=SC2086 # split into fields on purpose; they are numbers and letters
    set -- ${stat##*\) }
    [ "$1" != Z ] && [ "${20}" = "$start" ]
}

gone() {
    state=$(sed 's/.*) //' "/proc/$1/stat" 2>/dev/null | cut -d ' ' -f 1)
    [ -z "$state" ] || [ "$state" = Z ]
}

wait_gone() {
    for _ in $(seq 100); do
        gone "$1" && return 0
        sleep 0.1
    done
    return 1
}

# An immediate shutdown of the cluster's postmaster, which exits after its backends; SIGKILL if it will not.
stop_server() {
    pidfile="$1/data/postmaster.pid"
    [ -f "$pidfile" ] || return 0
    pid=$(head -n 1 "$pidfile")
    case "$pid" in '' | *[!0-9]*) return 0 ;; esac
    # Only this data directory's postmaster, not whichever process has its pid by now.
    cmdline=$(tr '\0' ' ' < "/proc/$pid/cmdline" 2>/dev/null)
    case "$cmdline" in
        *postgres*" -D "*"/${1##*/}/data "*) ;;
        *) return 0 ;;
    esac
    echo "pgcluster: stopping the server of $1 (pid $pid)"
    kill -QUIT "$pid" 2>/dev/null
    wait_gone "$pid" && return 0
    kill -KILL "$pid" 2>/dev/null
    wait_gone "$pid"
    # A killed postmaster leaves its System V segment (line 7 of postmaster.pid: key and id).
    # shellcheck disable=SC2046 # split into fields on purpose
    set -- $(sed -n 7p "$pidfile")
    [ -n "$2" ] && ipcrm -m "$2" 2>/dev/null
    return 0
}

[ -d "$root" ] || exit 0
for dir in "$root"/cluster-*; do
    [ -d "$dir" ] || continue
    owner_alive "$dir" && continue
    stop_server "$dir"
    rm -rf "$dir" && echo "pgcluster: removed $dir, whose test process is gone"
done
rmdir "$root" 2>/dev/null
exit 0
