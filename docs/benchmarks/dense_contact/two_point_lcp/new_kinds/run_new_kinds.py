#!/usr/bin/env python3
# Edge-to-edge impact chains and a tracked strike (scenes in this folder) on native before and after,
# in both regimes, and on Bullet x1: the last cube's speed against the closed form.
# usage: python3 run_new_kinds.py BEFORE_VROC AFTER_VROC   (run from this folder)
import json, csv, subprocess, sys, tempfile, math
scenes={'edge_chain_e1':(1.0,6,False),'edge_chain_e05_mu05':(0.5,6,False),'edge_chain_e05_cd2mm_gap0.4':(0.5,6,False),'tracked_edge_strike_e05':(0.5,2,True)}
def expect(e,n,tracked):
    # the first pass of sequential impacts of equal masses (the last cube's speed; later catch-ups of
    # the slower cubes are not modelled); tracked: an infinite-mass striker
    if tracked: return {f'c{n-1}':(1+e)*1.0}
    v=[1.0]+[0.0]*(n-1)
    for i in range(n-1):
        a,b=v[i],v[i+1]
        v[i]=a*(1-e)/2; v[i+1]=a*(1+e)/2
    return {f'c{i}':v[i] for i in range(n)}
for name,(e,n,tr) in scenes.items():
    ex=expect(e,n,tr)
    for label,binary,be,sets in [('before default',sys.argv[1],'native',[]),('after default',sys.argv[2],'native',[]),
                                 ('before fixed',sys.argv[1],'native',['--set','native.touching=fixed']),('after fixed',sys.argv[2],'native',['--set','native.touching=fixed']),
                                 ('bullet x1',sys.argv[2],'bullet',[])]:
        out=tempfile.mkdtemp()
        r=subprocess.run([binary,'run',name+'.json','--backend',be,'--duration','3','--out',out,'-q','--no-view']+sets,capture_output=True,text=True)
        if r.returncode: print(name,label,'FAILED',r.stderr[:300]); continue
        last={}
        for row in csv.DictReader(open(out+'/trajectory.csv')): last[row['body']]=row
        j=json.load(open(out+'/run.json'))
        err=abs(float(last[f'c{n-1}']['vx'])-ex[f'c{n-1}'])
        spin=max(math.sqrt(sum(float(last[b][k])**2 for k in ('wx','wy','wz'))) for b in last if b!='c0' or not tr)
        w=j['step_wall_time_us']
        print(f"{name:30s} {label:15s} last vx {float(last[f'c{n-1}']['vx']):.9f} (expect {ex[f'c{n-1}']:.9f}) |dv last| {err:.2e} max |w| {spin:.1e} total {w['mean']*j['steps']/1e3:.2f} ms worst {w['max']/1e3:.3f} ms warn {j['warnings']} hash {j['state_hash'][:8]}")
