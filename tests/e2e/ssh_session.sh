#!/usr/bin/env bash
# End-to-end over a real SSH link (issue 61, item 4): sshd and ssh -tt, a session that edits
# way1.dat's tension, and a staff key's bytes and settle time at 9600 baud per glyph set.
# ssh_session.py says how; this wrapper holds CI's lock for tests timed to the 100 ms.
# Usage: ssh_session.sh APCS DATA_FOLDER [STAFF_KEYS [VARIANT ...]]
set -euo pipefail
source "$(dirname "$0")/one_at_a_time.sh"
exec python3 "$(dirname "$0")/ssh_session.py" "$@"
