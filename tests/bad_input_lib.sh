#!/usr/bin/env bash
# Shared by the bad-input suites (bad_input_test.sh, bad_gltf_test.sh): a scratch folder, and
# check(), which runs one case. Sourced with the path of pt as its argument.
set -uo pipefail
pt=$(realpath "$1")
gltf=$(realpath "$(dirname "$0")/../scenes/gltf")
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# check NAME STATUS TEXT pt-arguments...: runs pt with a fresh output path out/NAME.exr (unless
# the arguments name one) and checks status, text, and that a failed run wrote nothing.
check() {
  local name=$1 status=$2 text=$3
  shift 3
  mkdir -p out
  local output got
  output=$(timeout -k 5 120 "$pt" "$@" 2>&1) # -k: pt blocked in open() on a FIFO ignores TERM
  got=$?
  if [[ $got -ne $status ]]; then
    fail "$name: exit $got, expected $status; output: $(echo "$output" | head -3)"
  elif [[ "$output" != *"$text"* ]]; then
    fail "$name: output does not contain \"$text\": $(echo "$output" | head -3)"
  elif [[ "$output" == *"terminate called"* || "$output" == *"Segmentation"* || "$output" == *"Aborted"* ]]; then
    fail "$name: crashed: $output"
  fi
  if [[ $status -ne 0 && -n "$(ls -A out)" ]]; then fail "$name: a failed run left $(ls -A out)"; fi
  rm -rf out
}

# damaged_jpegs: whole.jpg, cut.jpg (its first 1300 bytes) and garbled.jpg (200 bytes of its
# entropy-coded data overwritten), in the scratch folder.
damaged_jpegs() {
  oiiotool --pattern checker:width=16:height=16 256x256 3 -d uint8 -o whole.jpg >/dev/null 2>&1
  head -c 1300 whole.jpg > cut.jpg
  /usr/bin/python3 -c "b = bytearray(open('whole.jpg', 'rb').read()); b[1300:1500] = b'Z' * 200; open('garbled.jpg', 'wb').write(b)"
}

# Ends the suite: its status is the number of failed checks (0: all passed).
finish() {
  if [[ $failures -gt 0 ]]; then
    echo "$failures bad-input checks failed"
    exit 1
  fi
  echo "all bad-input checks passed"
}
