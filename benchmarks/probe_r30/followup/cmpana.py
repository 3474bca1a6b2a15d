"""cmpana.py OLD.json NEW.json: verdict, p, region, causes, refuted, region-check failures"""
import sys, json
o, n = (json.load(open(f)) for f in sys.argv[1:3])
name = sys.argv[2].rsplit("_new", 1)[0]
same = all(o.get(k) == n.get(k) for k in ("verdict", "p_success", "safe_region", "causes"))
ref = [r for r in (n.get("critical_refuted") or []) if r]
print(f"{name}: {'SAME' if same else 'CHANGED'} | old {o['verdict']} p={o['p_success']:.3f} {o.get('safe_region')} fails {len(o.get('region_failures') or [])}/{len(o.get('region_check') or [])}"
      f" | new {n['verdict']} p={n['p_success']:.3f} {n.get('safe_region')} fails {len(n.get('region_failures') or [])}/{len(n.get('region_check') or [])} | refuted {ref} | wall {o['wall']} {n['wall']}")
if o.get("causes") != n.get("causes"):
    print("   causes old:", o.get("causes")); print("   causes new:", n.get("causes"))
for r in (n.get("region_failures") or []): print("   NEW REGION FAIL", r)
for r in (o.get("region_failures") or []): print("   old region fail", r)
