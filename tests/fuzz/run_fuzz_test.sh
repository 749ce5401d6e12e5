#!/usr/bin/env bash
# Runs one bounded fuzz run for ctest and, when it fails, prints each input it saved as gzip +
# base64, so that a failure on a machine we cannot reach (CI) still carries its input in the
# log. Restore one with: base64 -d <<<'...' | gunzip > crash-input
#   run_fuzz_test.sh ARTIFACT_DIR FUZZER [LIBFUZZER ARGS...]
set -u
artifacts=$1
shift
mkdir -p "$artifacts" || exit 1
started=$(mktemp) || exit 1
"$@" -artifact_prefix="$artifacts/"
status=$?
if [ $status -ne 0 ]; then
  find "$artifacts" -type f -newer "$started" | while read -r input; do
    echo "input $(basename "$input") ($(stat -c %s "$input") bytes), gzip + base64:"
    gzip -9c "$input" | base64 -w 0
    echo
  done
fi
rm -f "$started"
exit $status
