#!/usr/bin/env bash
# A command that must fail cleanly: a non-zero exit that is not a crash (signals give 128+),
# and one line on stderr matching PATTERN.
#   cli_error_test.sh PATTERN COMMAND [ARGS...]
set -u
pattern=$1
shift
stderr=$("$@" 2>&1 >/dev/null)
status=$?
echo "exit $status: $stderr"
if [ $status -eq 0 ]; then echo "FAILED: the command succeeded"; exit 1; fi
if [ $status -ge 128 ]; then echo "FAILED: the command crashed"; exit 1; fi
if ! grep -qE -- "$pattern" <<<"$stderr"; then echo "FAILED: stderr does not match '$pattern'"; exit 1; fi
if [ "$(grep -c . <<<"$stderr")" -ne 1 ]; then echo "FAILED: the error is not one line"; exit 1; fi
