#!/usr/bin/env bash
# check_stc_tours.sh DETERMINISM ANTKIT MAPS: antkit_determinism --stc-tours (the listing that
# scripts/determinism.sh compares across CPUs) gives, for every shared map and variant it lists,
# the hash, covered, repeats and returned_to_start of `antkit stc --map F --variant V` (the same
# start: neither is given one). Fails on any difference, and on a listing that misses a map.
set -euo pipefail
det=$1 antkit=$2 maps=$3
listing=$("$det" --maps "$maps" --stc-tours)
want=$(( $(find "$maps/movingai" -name '*.map' | wc -l) + $(find "$maps/ros" -name '*.yaml' | wc -l) ))
lines=$(wc -l <<<"$listing")
if [ "$lines" -ne $((3 * want)) ]; then
  echo "FAIL: $lines lines, expected 3 per map for $want maps"
  exit 1
fi
failed=0
while read -r name hash covered repeats returned; do
  variant=$(cut -d/ -f2 <<<"$name")
  file=$(cut -d/ -f3 <<<"$name")
  case "$file" in *.map) path=$maps/movingai/$file ;; *) path=$maps/ros/$file ;; esac
  got=$("$antkit" stc --map "$path" --variant "$variant" --format json |
    jq -r '"\(.hash) \(.covered) \(.repeats) \(.returned_to_start)"')
  if [ "$got" != "$hash $covered $repeats $returned" ]; then
    echo "FAIL $name: antkit stc $got, listing $hash $covered $repeats $returned"
    failed=1
  fi
done <<<"$listing"
[ $failed -eq 0 ] && echo "ok: $lines tours on $want maps, the listing is antkit stc's"
exit $failed
