"""Level 7's outputs extrapolated from levels 5-7, as the estimate computes them, against level
9 and against level 8's own error, on the sample of examples/estimate_study.rs
(docs/ACCURACY_NOTES.md, "Level 7's friction extrapolated as the reported value"):
`python3 docs/extrapolated_friction.py [OUTPUT]` from the crate's root, OUTPUT one of
mu_bar_sliding (default), h_central, h_min (Python 3, no packages). Prints per case the relative
errors (%) of level 7, level 8 and the extrapolation, and how the order was read, then
[cases extrapolated, of them at or below level 8's error, 0]."""
import json, math, sys
rows=[json.loads(l) for l in open('docs/estimate-study.jsonl') if l.strip()]
def fitted(v):
    d=[b-a for a,b in zip(v,v[1:])]
    if len(d)<2 or any(x==0 for x in d): return None
    l=[math.log2(abs(x)) for x in d]; n=len(l); mi=(n-1)/2; ml=sum(l)/n
    return -sum((i-mi)*(y-ml) for i,y in enumerate(l))/sum((i-mi)**2 for i in range(n))
def extrap(lv,o):
    hf=lv[-1]["h_central"]; read=[]; stopped=False
    for x in reversed(lv):
        if x["h_central"]<0.5*hf: stopped=True; break
        read.insert(0,x)
    v=[x[o] for x in read]; d=[b-a for a,b in zip(v,v[1:])]
    if not d: return None,None
    if len(d)==1:
        p=2.0 if stopped else 1.0
        return v[-1]+d[-1]/(2**p-1), 'two'
    osc=any(a*b<0 for a,b in zip(d,d[1:])); p=fitted(v)
    if osc or p is None or p>4: return None,'osc'
    p=min(max(p,1),2); return v[-1]+d[-1]/(2**p-1), p
o=sys.argv[1] if len(sys.argv)>1 else "mu_bar_sliding"
print(f"{'case':40s} {'e7':>8s} {'e8':>8s} {'R57':>8s} {'how'}")
cnt=[0,0,0]
for r in [r for r in rows if r.get("levels")]:
    lv={x["level"]:x for x in r["levels"]}
    if 9 not in lv or 7 not in lv or 8 not in lv: continue
    ref=lv[9][o]
    seq=[lv[k] for k in sorted(lv) if k<=7]
    xr,how=extrap(seq,o)
    e=lambda x: abs(x/ref-1)*100
    s=f"{r['case'][:40]:40s} {e(lv[7][o]):8.3f} {e(lv[8][o]):8.3f} "
    if xr is None: s+=f"{'-':>8s} {how}"
    else:
        s+=f"{e(xr):8.3f} {how}"
        cnt[0]+=1; cnt[1]+= e(xr)<=e(lv[8][o]); 
    print(s)
print(cnt)
