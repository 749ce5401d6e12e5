#!/usr/bin/env bash
# A write that fails part way (the shell's file size limit, ulimit -f, stops it) must leave the
# file that was there unchanged, leave no temporary file, and fail cleanly: a non-zero exit that
# is not a crash, one line on stderr naming the file.
#   cli_failed_write_test.sh WORKDIR NAME COMMAND [ARGS...]
# Creates WORKDIR/NAME with known bytes, then runs COMMAND (whose output should be that file)
# from WORKDIR with a 1 KiB file size limit.
set -u
workdir=$1
name=$2
shift 2
rm -rf "$workdir" && mkdir -p "$workdir" && cd "$workdir" || exit 1
old="radview test: the old file, which a failed write must leave as it is"
printf '%s' "$old" >"$name"
stderr=$( (ulimit -f 1; "$@") 2>&1 >/dev/null)
status=$?
echo "exit $status: $stderr"
if [ $status -eq 0 ]; then echo "FAILED: the command succeeded"; exit 1; fi
if [ $status -ge 128 ]; then echo "FAILED: the command crashed"; exit 1; fi
if ! grep -qE -- "$name: writing failed.*the existing file is left unchanged" <<<"$stderr"; then
  echo "FAILED: stderr does not say that writing $name failed and the file is unchanged"; exit 1
fi
if [ "$(grep -c . <<<"$stderr")" -ne 1 ]; then echo "FAILED: the error is not one line"; exit 1; fi
if [ "$(cat "$name")" != "$old" ]; then echo "FAILED: $name was changed"; exit 1; fi
left=$(ls -A)
if [ "$left" != "$name" ]; then echo "FAILED: files left besides $name: $left"; exit 1; fi
echo "ok: $name unchanged, nothing else left"
