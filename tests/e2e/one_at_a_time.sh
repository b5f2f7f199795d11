# Sourced first by the end-to-end tests that need the machine to themselves: tmux servers, real
# terminals on a virtual X server, pseudo-terminals timed to 100 ms, signals at given moments.
# CTest's RUN_SERIAL keeps them apart within one ctest run only, and CI runs two builds' suites side
# by side (.ci/run). With APCS_TERMINAL_TEST_LOCK naming a lock file (.ci/run sets it for both), the
# test runs again under flock(1) on it: one such test at a time across both runs. flock holds the
# lock in its own process, so the tmux servers a test starts do not inherit it.
if [ -n "${APCS_TERMINAL_TEST_LOCK:-}" ]; then
  exec flock "$APCS_TERMINAL_TEST_LOCK" env APCS_TERMINAL_TEST_LOCK= bash "$0" "$@"
fi
