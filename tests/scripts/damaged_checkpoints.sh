#!/bin/sh
# Issue 39: damages each file of the newest checkpoint in turn (16 bytes
# inverted in its middle, cut to half its size, removed) and restarts from
# it: every case must be refused with exit status 1, a message naming the
# file, and the output directory exactly as it was. Then the intact
# checkpoint restarts.
# usage: damaged_checkpoints.sh "<launcher> <executable>" run.prm later.prm
# (later.prm: run.prm with a later End time, for the intact restart)
set -u
run=$1
prm=$2
later=$3
$run "$prm" > first.log 2>&1 || { echo "the first run failed"; tail -5 first.log; exit 1; }
checkpoint=$(ls -d out/checkpoints/step-* | sort | tail -n 1)
rm -rf pristine
cp -r "$checkpoint" pristine
state() { find out -type f | sort | xargs md5sum; }
cases=0
refused=0
for file in $(ls pristine); do
  for how in flip truncate delete; do
    rm -rf "$checkpoint"
    cp -r pristine "$checkpoint"
    size=$(wc -c < "$checkpoint/$file")
    case $how in
      flip)
        [ "$size" -gt 0 ] || continue
        python3 -c "
import sys
f, n = sys.argv[1], int(sys.argv[2])
b = bytearray(open(f, 'rb').read())
for i in range(n // 2, min(n, n // 2 + 16)):
    b[i] ^= 0xFF
open(f, 'wb').write(b)" "$checkpoint/$file" "$size" ;;
      truncate)
        [ "$size" -gt 1 ] || continue
        truncate -s $((size / 2)) "$checkpoint/$file" ;;
      delete)
        rm "$checkpoint/$file" ;;
    esac
    cases=$((cases + 1))
    before=$(state)
    $run --restart out > restart.log 2>&1
    status=$?
    after=$(state)
    if [ "$file" = checksums ]; then
      named="is damaged: its file '|cannot be verified"
    else
      named="is damaged: its file '$file'"
    fi
    if [ $status -eq 1 ] && grep -Eq "$named" restart.log && [ "$before" = "$after" ] \
       && [ "$(grep -c 'Error' restart.log)" -eq 1 ] && ! grep -q MPI_ABORT restart.log; then
      refused=$((refused + 1))
    else
      echo "NOT REFUSED: $file $how (exit status $status)"
      tail -3 restart.log
    fi
  done
done
# a list cut at a line boundary (its first line removed: the file it
# named would go unchecked)
rm -rf "$checkpoint"
cp -r pristine "$checkpoint"
sed -i 1d "$checkpoint/checksums"
cases=$((cases + 1))
before=$(state)
$run --restart out > restart.log 2>&1
status=$?
if [ $status -eq 1 ] && grep -q "is damaged: its file 'checksums' lists" restart.log && [ "$before" = "$(state)" ]; then
  refused=$((refused + 1))
else
  echo "NOT REFUSED: checksums without its first line (exit status $status)"
  tail -3 restart.log
fi
echo "refused $refused of $cases damaged checkpoints"
[ $refused -eq $cases ] && [ $cases -ge 6 ] && echo "every damaged checkpoint refused"
rm -rf "$checkpoint"
cp -r pristine "$checkpoint"
$run --restart out "$later" > restart.log 2>&1
echo "intact checkpoint: exit status $?"
