#!/usr/bin/env bash
# Writes the expected outputs of tests/golden/cases.txt with the binaries in target/release
# (run once, from the repository root, before a change that must keep the output).
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=tests/golden
while IFS=$'\t' read -r name cmd; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  prog=${cmd%% *}
  args=${cmd#* }
  # shellcheck disable=SC2086
  (cd "$dir" && "../../target/release/$prog" $args) > "$dir/$name.out"
  sed -i "s#\.\./\.\./target/release/$prog#$prog#g" "$dir/$name.out"
done < "$dir/cases.txt"
