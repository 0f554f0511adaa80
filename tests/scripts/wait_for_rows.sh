# usage: sh wait_for_rows.sh FILE N
# Waits (up to 60 s) until FILE (a statistics.csv being written by a run in
# the background) has at least N lines: the reliability tests signal a run
# at a known point of it.
wait_file=$1; wait_rows=$2; wait_i=0
while [ $wait_i -lt 3000 ]; do
  if [ -f "$wait_file" ] && [ "$(wc -l < "$wait_file")" -ge "$wait_rows" ]; then break; fi
  sleep 0.02; wait_i=$((wait_i + 1))
done
