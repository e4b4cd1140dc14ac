#!/bin/bash
# every untuned variant, before (cee98e5) and after (HEAD), fixed ticks 2 s and default 1 s: state hash, deepest, total
for f in ${DIR:?variants folder}/*.json; do
  n=$(basename $f .json)
  for R in fixed protected; do
    D=2; [ $R = protected ] && D=1
    case $n in pyramid100*) D=0.5;; esac
    line="$n $R ${D}s"
    for V in ${BEFORE:?vroc binary before} ${AFTER:?vroc binary after}; do
      o=$(mktemp -d)
      $V run $f --backend native --duration $D -q --no-view --out $o --set native.touching=$R --set native.threads=1 2>/dev/null
      r=$(python3 -c "
import json;j=json.load(open('$o/run.json'));s=j['statistics'];sw=j['step_wall_time_us']
print(j['state_hash'][:10], '%.3f'%(s.get('native.deepest_penetration_m',0)*1e3), '%.3f'%(sw['mean']*j['steps']*1e-6), '%.1f'%(sw['max']*1e-3), int(j['warnings'].get('penetration_recovered',0)))" 2>/dev/null)
      line="$line | $r"; rm -rf $o
    done
    echo "$line"
  done
done
