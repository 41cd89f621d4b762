#!/usr/bin/env python3
"""Tau-extrapolation against the estimate study's finest levels (docs/ACCURACY_NOTES.md,
"Tau-extrapolation, measured").

    python3 docs/tau_study.py docs/estimate-study.jsonl docs/tau-study-7.jsonl [...]

Each line of a tau file (`cargo run --release --example tau_study -- --level N CASE...`) holds
one case's level-N outputs and their tau-extrapolation; the study file the same case's levels
up to the finest the solver reaches (9 on one domain). Per output: how far the level and its
extrapolation are from the finest, and the estimate `|tau - level|` (times a safety factor)
against the level's distance to the finest."""
import json
import statistics
import sys

OUTPUTS = (("Hc", "h_central"), ("Hmin", "h_min"), ("mu-bar", "mu_bar_sliding"))
SAFETY = (1.0, 1.25, 2.0, 3.0)


def load(path):
    return [json.loads(line) for line in open(path) if line.strip()]


def main():
    finest = {}
    for d in load(sys.argv[1]):
        if d.get("levels"):
            levels = {x["level"]: x for x in d["levels"]}
            finest[d["case"]] = (max(levels), levels)
    for path in sys.argv[2:]:
        rows = [d for d in load(path) if "error" not in d and d["case"] in finest]
        rows = [d for d in rows if finest[d["case"]][0] > d["level"]]
        if not rows:
            continue
        level = rows[0]["level"]
        print(f"\n{path}: {len(rows)} cases at level {level}, against their finest level")
        print("| output | level's error: median, max | tau's error: median, max | tau closer |"
              + "".join(f" x{s}: brackets / median, max over |" for s in SAFETY))
        print("|---|---|---|---|" + "---|" * len(SAFETY))
        for name, key in OUTPUTS:
            level_err, tau_err, ratio = [], [], []
            for d in rows:
                top, levels = finest[d["case"]]
                truth = levels[top][key]
                dist = abs(d[key] - truth) / abs(truth)
                level_err.append(dist)
                tau_err.append(abs(d["tau_" + key] - truth) / abs(truth))
                est = abs(d["tau_" + key] - d[key]) / abs(truth)
                ratio.append(est / dist if dist > 0 else float("inf"))
            closer = sum(t < e for t, e in zip(tau_err, level_err))
            cells = []
            for s in SAFETY:
                over = [s * r for r in ratio]
                cells.append(f" {sum(o >= 1 for o in over)}/{len(over)} / "
                             f"{statistics.median(over):.2f}, {max(over):.1f} |")
            print(f"| {name} | {100 * statistics.median(level_err):.3g} %, "
                  f"{100 * max(level_err):.3g} % | {100 * statistics.median(tau_err):.3g} %, "
                  f"{100 * max(tau_err):.3g} % | {closer}/{len(rows)} |" + "".join(cells))
        over_target = [d for d in rows if abs(d["tau_mu_bar_sliding"] - d["mu_bar_sliding"])
                       > 0.01 * abs(d["mu_bar_sliding"])]
        truly = [d for d in rows if abs(d["mu_bar_sliding"] - finest[d["case"]][1][finest[d["case"]][0]]
                                        ["mu_bar_sliding"]) > 0.01 * abs(d["mu_bar_sliding"])]
        print(f"mu-bar estimate above 1 % (x1): {len(over_target)}; level truly more than 1 % off: "
              f"{len(truly)}; both: {len(set(d['case'] for d in over_target) & set(d['case'] for d in truly))}")


if __name__ == "__main__":
    main()
