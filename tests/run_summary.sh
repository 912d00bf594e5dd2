#!/usr/bin/env bash
# run_summary.sh MESHPARTICLES MESHES WORKDIR: the summary `run` prints says
# what its report.json says, for each method: the mesh, spread's working
# mesh and sweeps, paper's backend, device, scheme, iterations, energies and
# update kernels' time, and the quality line's figures.
set -euo pipefail
bin=$1 meshes=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# spread (the default), paper on the host, paper on a device backend (it times its kernels).
"$bin" run "$meshes/torus.off" -n 40 --seed 3 -q --no-cache --out "$work/spread" > "$work/spread.txt"
"$bin" run "$meshes/torus.off" -n 40 --method paper --backend serial -q --no-cache --out "$work/serial" \
  > "$work/serial.txt"
"$bin" run "$meshes/torus.off" -n 40 --method paper --backend naive -q --no-cache --out "$work/naive" \
  > "$work/naive.txt"
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
for name in ("spread", "serial", "naive"):
    report = json.load(open(f"{work}/{name}/report.json"))
    params = report["params"]
    printed = dict((line[:12].strip(), line[12:]) for line in open(f"{work}/{name}.txt").read().splitlines())
    expected = {"mesh": f"{report['mesh']['path']} ({report['mesh']['vertices']} vertices)"}
    quality = report["quality"]
    assert printed["quality"].startswith(f"nn min {quality['nn_min']:.4g} mean {quality['nn_mean']:.4g}"), \
        (name, printed["quality"])
    assert f"energy {quality['energy']:.6g}, " in printed["quality"], (name, printed["quality"])
    if params["method"] == "spread":
        working = report["working_mesh"]
        expected["particles"] = (f"{params['n']}, spread on a working mesh of {working['vertices']} vertices "
                                 f"({working['refinement_rounds']} rounds of splitting edges)")
        expected["sweeps"] = f"{report['iterations_run']} ({report['stopped']})"
        expected["time"] = f"{report['avg_iteration_ms']:.3f} ms/sweep"
    else:
        expected["particles"] = f"{params['n']}, {params['backend']} on {report['device']}, scheme {params['scheme']}"
        expected["iterations"] = f"{report['iterations_run']} ({report['stopped']})"
        expected["energy"] = f"{report['initial_energy']:.6g} -> {report['final_energy']:.6g}"
        expected["time"] = f"{report['avg_iteration_ms']:.3f} ms/iteration"
        if "avg_kernel_ms" in report:
            expected["time"] += f" (update kernels {report['avg_kernel_ms']:.3f} ms)"
    for key, line in expected.items():
        if printed.get(key) != line:
            sys.exit(f"FAIL: {name}: the summary's {key!r} line is {printed.get(key)!r}, report.json says {line!r}")
    assert ("sweeps" in printed) == (params["method"] == "spread"), (name, sorted(printed))
assert "update kernels" in open(f"{work}/naive.txt").read(), "a device backend's kernel time is printed"
print("ok: spread's, serial's and naive's summaries are their reports'")
PY
