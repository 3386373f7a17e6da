#!/usr/bin/env bash
# The POV-Ray oracle: random scenes rendered by rtrender and by POV-Ray 3.7 must agree.
#   run_oracle.sh RTRENDER RTGOLDEN WORK_DIR FIRST_SEED COUNT [GENERATOR_FLAGS...]
# Each seed's scene (tests/oracle/oracle_scene.py) is traced by both at 200 x 150; a seed
# passes when at most 0.1 % of its pixels differ by more than 2/255 in any channel.
# A failing seed prints the commands that reproduce it; its images stay in WORK_DIR.
set -u
rtrender=$1 rtgolden=$2 work=$3 first=$4 count=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
command -v povray >/dev/null || { echo "oracle: povray is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
mkdir -p "$work"
failed=0
for ((seed = first; seed < first + count; ++seed)); do
  dir=$work/seed$seed
  rm -rf "$dir"
  generate=(python3 "$here/oracle_scene.py" "$seed" "$dir" "$@")
  "${generate[@]}" || { echo "seed $seed: the generator failed"; failed=1; continue; }
  # POV-Ray reads and writes only below its working folder (its default I/O security).
  pov=(povray +Iscene.pov +Opov.png +W200 +H150 -A -D +FN File_Gamma=sRGB -GA +WT1)
  if ! (cd "$dir" && "${pov[@]}" >pov.log 2>&1); then
    echo "seed $seed: povray failed:"; tail -5 "$dir/pov.log"; failed=1; continue
  fi
  trace=("$rtrender" "$dir/scene.json" -o "$dir/rtview.png" --mode trace --min-weight 0 --quiet)
  "${trace[@]}" || { echo "seed $seed: rtrender failed"; failed=1; continue; }
  if result=$("$rtgolden" compare "seed$seed" "$dir/rtview.png" "$dir" "$dir/report" \
                --as pov --fail 0.008 --fail-percent 0.1 --edges -1 2>&1); then
    echo "seed $seed: $result"
  else
    failed=1
    echo "seed $seed: DIFFERS: $result"
    echo "  reproduce: ${generate[*]}"
    echo "             (cd $dir && ${pov[*]})"
    echo "             ${trace[*]}"
    echo "  images: $dir/rtview.png beside $dir/pov.png; report $dir/report"
  fi
done
exit $failed
