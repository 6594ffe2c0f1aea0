# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""The deformation-capacity study's report: tables, targets, pictures and
the README block, from the runs' records (see run)."""
import json
import os

from studySetup import *  # noqa: F401,F403 (the study's set-up)


def fmt(x, nd=3):
    return "-" if x is None else ("%.*f" % (nd, x))


def quality_at(rec, deg):
    for a, q in zip(rec["angles"], rec["minQ"]):
        if abs(a - deg) < 1e-6:
            return "%.3f" % q if q > 0 else "inv"
    if rec["firstInvalid"] is not None and rec["firstInvalid"] < deg:
        return "inv"
    return "-"


def checkpoints(m, S=1):
    """Steps (amplitudes in 1x units at ramp scale S) at which the table
    gives the minimum quality."""
    cp = (10, 20, 30) if is3D(m) else (15, 30, 45)
    return cp if S == 1 else tuple(round(c*S, 9) for c in cp)


def table(runs, features):
    lines = []
    order = {c["key"]: i for i, c in enumerate(CONFIGS)}
    scale = lambda r: r.get("scale", 1)  # noqa: E731
    for m, S in sorted({(r["mesh"], scale(r)) for r in runs.values()},
                       key=lambda x: (x[1] != 1, x[0], -x[1])):
        cp = checkpoints(m, S)
        if S == 1:
            lines.append("\n### Mesh %s: %s, supportRadius %g\n" % (
                m, MESHES[m]["title"], MESHES[m]["supportRadius"]))
        else:
            lines.append("\n### Mesh %s at ramp scale %g (%s per step): %s, supportRadius %g\n" % (
                m, S, stepLabel(m, S, S), MESHES[m]["title"], MESHES[m]["supportRadius"]))
        if is3D(m) and S == 1:
            lines.append("Step k: tip deflection %g k semi-spans (%.4f k m), tip twist %g k deg.\n"
                         % (WING_DEFL_STEP, WING_DEFL_STEP*WING_SEMISPAN, WING_TWIST_STEP))
            lines.append("| configuration | boundaryCorrection | N (first -> last) | first invalid step "
                         "(tip deflection, twist) | min q at step %d | at %d | at %d | dcpRBF ms/step "
                         "| wall ms/step |" % cp)
        elif is3D(m):
            lines.append("Amplitudes in physical units: tip deflection (m, %% of the semi-span b) and "
                         "tip twist; %g steps of the scaled ramp = one step of the default ramp.\n"
                         % (1/S))
            lines.append("| configuration | boundaryCorrection | N (first -> last) | first invalid "
                         "amplitude (tip deflection, twist) | min q at %s | at %s | at %s | dcpRBF ms/step "
                         "| wall ms/step |" % tuple(stepLabel(m, c, S) for c in cp))
        else:
            lines.append("| configuration | boundaryCorrection | N (first -> last) | first invalid angle%s "
                         "| min q at %g deg | at %g deg | at %g deg | dcpRBF ms/step | wall ms/step |" % (
                             (" (deg)" if S == 1 else "",) + cp))
        lines.append("|---|---|---|---|---|---|---|---|---|")
        keys = sorted((k for k, r in runs.items() if r["mesh"] == m and scale(r) == S),
                      key=lambda k: (order[runs[k]["config"]], runs[k]["correction"] or "",
                                     runs[k]["N"] or 0))
        for k in keys:
            r = runs[k]
            if r.get("skipped"):
                lines.append("| %s | %s | %s | skipped: %s | | | | | |" % (
                    r["label"], r["correction"] or "-", r["N"] or "-", r["skipped"]))
                continue
            if r.get("error"):
                lines.append("| %s | %s | %s | error: %s | | | | | |" % (
                    r["label"], r["correction"] or "-", r["N"] or "-",
                    r["error"].splitlines()[-1][:80]))
                continue
            n = "%d -> %d" % (r["nControl"][0], r["nControl"][-1]) if r["nControl"] \
                else str(r["N"] or "-")
            if S == 1:
                inv = stepLabel(m, r["firstInvalid"]) if r["firstInvalid"] is not None \
                    else "> %d (cap)" % r["cap"]
            else:
                inv = stepLabel(m, r["firstInvalid"], S) if r["firstInvalid"] is not None \
                    else "> %s (cap)" % stepLabel(m, r["cap"], S)
            lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %.0f |" % (
                r["label"], r["correction"] or "-", n, inv, quality_at(r, cp[0]),
                quality_at(r, cp[1]), quality_at(r, cp[2]),
                "%.1f" % r["dcpMs"] if r["steps"] else "-", r["wallMs"]))
    head = ("Deformation capacity (moveDynamicMesh, WendlandC2 + linear polynomial, no quality "
            "guard): 2D meshes a, b: rigid pitch about the quarter chord, +1 deg per step; "
            "3D wing c: bending + twist ramp, +%g %% of the semi-span and +%g deg at the tip "
            "per step. " % (100*WING_DEFL_STEP, WING_TWIST_STEP) +
            "swapRule keyword in the library: %s.\n" %
            ("yes" if features.get("swapRule") else "no (DCP paper rule = selection dynamic)"))
    return head + "\n".join(lines) + "\n"


def last_valid(r):
    """(amplitude of the last valid step in 1x-step units, capped?) of a
    scaled run: first invalid - one scaled step, or the cap if none."""
    if r.get("firstInvalid") is None:
        return r["cap"], True
    return round(r["firstInvalid"] - r["scale"], 9), False


def finer_steps(runs):
    """targets.md section 1b: the paper setting (correction off) at ramp
    scales != 1, amplitudes in physical units; [] without such runs."""
    scaled = sorted({(r["mesh"], r["N"], r["scale"]) for r in runs.values()
                     if r.get("scale", 1) != 1 and r["correction"] == "off" and r["N"]},
                    key=lambda x: (x[0], x[1], -x[2]))
    if not scaled:
        return []
    out = ["\n### 1b. Paper setting at finer steps (`--ramp-scale S`: S x the increment per step, "
           "same motion): new rule / static greedy, last valid amplitude (target >= 1.5 on b and c, "
           "N 20 and 50)\n",
           "Amplitude = last valid step x S in physical units (2D: pitch angle; 3D: tip deflection, "
           "tip twist); '>=' : no inverted cell up to the cap. Ratios of amplitudes (on c tip "
           "deflection and twist grow together, one ratio).\n",
           "| mesh | N | S | greedy | DCP new rule | ratio | DCP paper rule | ratio |",
           "|---|---|---|---|---|---|---|---|"]
    for m, N, S in scaled:
        G, D, P = (runs.get("%s_%s_N%d_corroff%s" % (m, c, N, scaleTag(S)))
                   for c in ("greedy", "dcpNew", "dcpPaper"))
        if not G or G.get("skipped") or G.get("error"):
            continue

        def amp(r):
            if not r or r.get("skipped") or r.get("error"):
                return "-", None, False
            a, capped = last_valid(r)
            if a <= 0:
                return "none (step 1 inverts)", a, capped
            return (">= " if capped else "") + stepLabel(m, a, S), a, capped

        g, ga, _ = amp(G)
        row = "| %s | %d | %g | %s |" % (m, N, S, g)
        for r in (D, P):
            t, a, capped = amp(r)
            if a is None:
                ratio = "-"
            elif ga <= 0:
                ratio = "-"
            else:
                ratio = ("%s%.2f" % (">= " if capped else "", a/ga))
            row += " %s | %s |" % (t, ratio)
        out.append(row)
    return out


def targets(runs):
    """Issue 8's targets, read from the runs: results/targets.md."""
    def get(m, c, N, corr):
        return runs.get("%s_%s_N%d_corr%s" % (m, c, N, corr))
    unit = lambda m: "step" if is3D(m) else "deg"  # noqa: E731
    meshes = sorted({r["mesh"] for r in runs.values()})
    out = ["Issue 8's targets, from results/runs.json (first invalid = first step with an "
           "inverted cell; amplitude = the last valid step = first invalid - 1).\n"]
    out += ["### 1. Paper setting (fixed N, boundaryCorrection off, no re-selection): "
            "new rule / static greedy, first invalid step (target >= 1.5 on b and c, N 20 and 50)\n",
            "| mesh | N | greedy | DCP new rule | ratio | DCP paper rule | ratio |", "|---|---|---|---|---|---|---|"]
    for m in meshes:
        for N in (20, 50, 100):
            G, D, P = (get(m, c, N, "off") for c in ("greedy", "dcpNew", "dcpPaper"))
            if not (G and D and P) or "firstInvalid" not in G:
                continue
            f = lambda r: r["firstInvalid"] if r.get("firstInvalid") is not None else r["cap"] + 1  # noqa: E731
            out.append("| %s | %d | %g | %g | %.2f | %g | %.2f |" % (
                m, N, f(G), f(D), f(D)/f(G), f(P), f(P)/f(G)))
    out += finer_steps(runs)
    for corr in ("off", "on"):
        out += ["\n### 2. Min quality of DCP >= greedy's at every step before greedy's first "
                "invalid step (boundaryCorrection %s): steps where it is lower by > 1e-3, "
                "largest deficit\n" % corr,
                "| mesh | N | greedy first invalid | new rule: steps lower | max deficit (at) "
                "| paper rule: steps lower | max deficit (at) |", "|---|---|---|---|---|---|---|"]
        for m in meshes:
            for N in (20, 50, 100):
                G = get(m, "greedy", N, corr)
                if not G or "firstInvalid" not in G:
                    continue
                lim = G["firstInvalid"] if G["firstInvalid"] is not None else G["cap"] + 1
                qg = dict(zip(G["angles"], G["minQ"]))
                row = ["%s | %d | %g" % (m, N, lim)]
                for c in ("dcpNew", "dcpPaper"):
                    D = get(m, c, N, corr)
                    if not D or "angles" not in D:
                        row.append("- | -")
                        continue
                    qd = dict(zip(D["angles"], D["minQ"]))
                    d = [(qg[t] - qd[t] if t in qd else float("inf"), t) for t in sorted(qg) if t < lim]
                    n = sum(1 for x, t in d if x > 1e-3)
                    w = max(d) if d else None
                    row.append("%d of %d | %s" % (n, len(d), "-" if w is None or w[0] <= 1e-3 else
                               ("inverted (%g)" % w[1] if w[0] == float("inf") else "%.3f (%g)" % w)))
                out.append("| " + " | ".join(row) + " |")
    out += ["\n### 3. Defaults (boundaryCorrection on, swapRule errorGuided, nSwap 4, "
            "swapBlendSteps 4) at fixed N: DCP first invalid >= greedy's\n",
            "| mesh | N | greedy | DCP new rule | met | DCP paper rule |", "|---|---|---|---|---|---|"]
    for m in meshes:
        for N in (20, 50, 100):
            G, D, P = (get(m, c, N, "on") for c in ("greedy", "dcpNew", "dcpPaper"))
            if not (G and D and P) or "firstInvalid" not in G:
                continue
            f = lambda r: r["firstInvalid"] if r.get("firstInvalid") is not None else r["cap"] + 1  # noqa: E731
            out.append("| %s | %d | %g | %g | %s | %g |" % (
                m, N, f(G), f(D), "yes" if f(D) >= f(G) else "no (%+g %s)" % (f(D) - f(G), unit(m)),
                f(P)))
    out += ["\n### 4. Cost: dcpRBF ms/step, DCP / static greedy (target <= 1.2; only runs of "
            "more than 2 steps; timings noisy on the shared machine)\n",
            "Mean over every step of the run (trial, rescue and selection steps included); in "
            "brackets the median over the steps after the first (a typical step). Last column: "
            "the new rule's mean over the steps greedy made too (a run that goes on past "
            "greedy's limit adds rescue steps greedy never paid for), over greedy's.\n",
            "| mesh | N | correction | greedy ms | new rule ms | new/greedy | paper rule ms | paper/greedy | new/greedy, same steps |",
            "|---|---|---|---|---|---|---|---|---|"]
    for m in meshes:
        for corr in ("off", "on"):
            for N in (20, 50, 100):
                G, D, P = (get(m, c, N, corr) for c in ("greedy", "dcpNew", "dcpPaper"))
                if not (G and D and P) or G.get("steps", 0) <= 2:
                    continue
                med = lambda r: r.get("dcpMedianMs", float("nan"))  # noqa: E731
                cell = lambda r: ("%.1f (%.1f) | %.2f (%.2f)" % (  # noqa: E731
                    r["dcpMs"], med(r), r["dcpMs"]/G["dcpMs"], med(r)/med(G))
                    if r.get("steps", 0) > 2 else "- | -")
                same = "-"
                if G.get("dtMs") and D.get("dtMs"):
                    k = min(len(G["dtMs"]), len(D["dtMs"]))
                    same = "%.2f" % (sum(D["dtMs"][:k])/sum(G["dtMs"][:k]))
                out.append("| %s | %d | %s | %.1f (%.1f) | %s | %s | %s |" % (
                    m, N, corr, G["dcpMs"], med(G), cell(D), cell(P), same))
    return "\n".join(out) + "\n"


def plot(runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(IMAGES, exist_ok=True)
    colours = {"all": "k", "greedy": "tab:blue", "greedyReselect": "tab:green",
               "dcpPaper": "tab:red", "dcpNew": "tab:purple"}
    styles = {None: "-", 20: ":", 50: "--", 100: "-"}
    for m, S in sorted({(r["mesh"], r.get("scale", 1)) for r in runs.values()}):
        ok = [r for k, r in sorted(runs.items()) if r["mesh"] == m and r.get("scale", 1) == S
              and not r.get("skipped") and not r.get("error") and r["angles"]]
        if not ok:
            continue
        corrs = sorted({r["correction"] for r in ok if r["correction"]}) or ["off"]
        width = 6*len(corrs) if S == 1 else max(8, 6*len(corrs))
        fig, axes = plt.subplots(1, len(corrs), figsize=(width, 4.6), squeeze=False,
                                 sharey=True)
        for ax, corr in zip(axes[0], corrs):
            for r in ok:
                if r["correction"] not in (None, corr):
                    continue
                lab = r["label"] + ("" if r["N"] is None else ", N %d" % r["N"])
                ax.plot(r["angles"], r["minQ"], styles.get(r["N"], "-"),
                        color=colours[r["config"]], lw=1.3, label=lab)
                if r["firstInvalid"] is not None:
                    ax.plot([r["firstInvalid"]], [0], "x", color=colours[r["config"]])
            ax.axhline(0, color="grey", lw=0.5)
            ax.set_ylim(-0.05, 1.02)
            if S != 1:
                ax.set_xlabel("amplitude in default steps (tip +%g %% b, +%g deg each)"
                              "; x: first inverted cell" % (100*WING_DEFL_STEP, WING_TWIST_STEP)
                              if is3D(m) else
                              "pitch angle (deg; %g deg per step); x: first inverted cell" % S)
            else:
                ax.set_xlabel("step (tip +%g %% b, +%g deg each); x: first inverted cell"
                              % (100*WING_DEFL_STEP, WING_TWIST_STEP) if is3D(m)
                              else "pitch angle (deg); x: first inverted cell")
            ax.set_title("boundaryCorrection %s" % corr, fontsize=9)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=6)
        axes[0][0].set_ylabel("min cell quality (within reach)")
        fig.suptitle("Mesh %s%s %s" % (m, ":" if S == 1 else " (ramp scale %g):\n" % S,
                                         MESHES[m]["title"]), fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(IMAGES, "minQuality_%s%s.png" % (m, scaleTag(S))), dpi=80)
        plt.close(fig)


README_BEGIN = "<!-- results: begin (written by ./run from results/table.md and results/targets.md) -->"
README_END = "<!-- results: end -->"


def write_results(data):
    """results/table.md, results/targets.md, the pictures, and both tables
    into README.md between README_BEGIN and README_END."""
    text = table(data["runs"], data["features"])
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write(text)
    print(text)
    tgt = targets(data["runs"])
    with open(os.path.join(RESULTS, "targets.md"), "w") as f:
        f.write(tgt)
    plot(data["runs"])
    readme = os.path.join(HERE, "README.md")
    txt = open(readme).read()
    if README_BEGIN in txt and README_END in txt:
        block = README_BEGIN + "\n\n" + text.rstrip("\n") + "\n\n" + tgt.rstrip("\n") + "\n\n" + README_END
        txt = txt[:txt.index(README_BEGIN)] + block + txt[txt.index(README_END) + len(README_END):]
        open(readme, "w").write(txt)


def replot():
    write_results(json.load(open(os.path.join(RESULTS, "runs.json"))))
