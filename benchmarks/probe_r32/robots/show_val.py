"""Print validate per_sample (mass, friction, outcome, predicted) sorted by mass. usage: show_val.py VAL.json"""
import json, sys
for f in sys.argv[1:]:
    d = json.load(open(f)); print(f, d['confusion'], d['agreement'], d['outcomes'], 'nominal_completed', d.get('nominal_completed'))
    for s in sorted(d['per_sample'], key=lambda s: tuple(s['values'].values())):
        v = s['values']
        flag = '' if s['real_failed'] == s['predicted_failed'] else ('  FALSE SAFE' if s['real_failed'] else '  FALSE UNSAFE')
        print(' '.join(f"{k}={x:.3f}" for k, x in v.items()), s['outcome'], 'pred_fail' if s['predicted_failed'] else 'pred_ok', 'verified' if s['verified'] else '', round(s['max_cost'], 3), flag)
