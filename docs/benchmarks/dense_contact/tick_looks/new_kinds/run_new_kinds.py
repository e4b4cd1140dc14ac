#!/usr/bin/env python3
# A tracked paddle strikes a box towards a thin real wall (scenes in this folder), native before and
# after on fixed ticks and in the default regime, and Bullet x1: the box's exit speeds and impact
# times against the closed form, and whether it ever passed the wall's near face.
# usage: python3 run_new_kinds.py BEFORE_VROC AFTER_VROC   (run from this folder)
import json, csv, math, subprocess, sys, tempfile
for name in ['paddle_box_wall_v20', 'paddle_box_wall_v60_cd2mm']:
    s = json.load(open(name + '.json'))
    v = s['bodies'][2]['linear_velocity'][0]; e = 0.5
    wall_face = s['bodies'][0]['position'][0] - 0.005
    t_strike = (0.25 - 0.05) / v   # the paddle's face at -0.2 m, the box's back face at 0
    t_wall = t_strike + (wall_face - 0.1) / ((1 + e) * v)
    print(f"{name}: closed form: strike at {t_strike:.5f} s, box leaves at {(1+e)*v:.3f} m/s, wall at {t_wall:.5f} s, returns at {-e*(1+e)*v:.3f} m/s")
    for label, binary, be, sets in [('before fixed', sys.argv[1], 'native', ['--set', 'native.touching=fixed']),
                                    ('after fixed', sys.argv[2], 'native', ['--set', 'native.touching=fixed']),
                                    ('after default', sys.argv[2], 'native', []), ('bullet x1', sys.argv[2], 'bullet', [])]:
        out = tempfile.mkdtemp()
        r = subprocess.run([binary, 'run', name + '.json', '--backend', be, '--duration', str(round(math.ceil(t_wall * 60.0) / 60.0 - 1e-4, 5)), '--out', out, '-q', '--no-view'] + sets, capture_output=True, text=True)
        if r.returncode: print(' ', label, 'FAILED', r.stderr[:200]); continue
        xmax, vx = -1e9, []
        for row in csv.DictReader(open(out + '/trajectory.csv')):
            if row['body'] == 'box': xmax = max(xmax, float(row['x']) + 0.05); vx.append(float(row['vx']))
        ev = [(float(x['t']), x['body_a'] + '-' + x['body_b']) for x in csv.DictReader(open(out + '/events.csv'))]
        j = json.load(open(out + '/run.json')); w = j['step_wall_time_us']
        print(f"  {label:13s} box front max {xmax:.4f} (wall face {wall_face:.4f}) passed: {xmax > wall_face + 1e-9}; vx after strike {max(vx):.6f}, last {vx[-1]:.6f}; "
              f"events {[(round(t, 5), p) for t, p in ev]}; total {w['mean']*j['steps']/1e3:.2f} ms worst {w['max']/1e3:.3f} ms warn {j['warnings']}")
