#!/usr/bin/env bash
# expect_run.sh OUT CHECKS REGEX COMMAND...: COMMAND writes a run's output set
# into OUT. It must exit 0 with stderr matching REGEX (expect_exit.sh), and
# OUT must then hold what the run promises: every file report.json lists in
# `outputs`, at the size and SHA-256 recorded there; particles.particles with
# params.n lines of three finite numbers and particles.csv with a header and
# as many rows; and each of CHECKS (space-separated), a dotted path into
# report.json then `=VALUE` (equal, VALUE read as JSON where it parses, else
# as a string), `>NUMBER` or `~TEXT` (the value's text contains TEXT).
# OUT is removed first: a run that wrote nothing cannot pass on an old set.
set -u
out=$1 checks=$2
shift 2
rm -rf "$out"
"$(dirname "$0")/expect_exit.sh" 0 "$@" || exit 1
exec python3 - "$out" "$checks" <<'PY'
import hashlib, json, math, pathlib, re, sys

out, checks = pathlib.Path(sys.argv[1]), sys.argv[2].split()
problems = []
report = json.loads((out / "report.json").read_text())
for name, recorded in report["outputs"].items():
    data = (out / name).read_bytes()
    if len(data) != recorded["bytes"] or hashlib.sha256(data).hexdigest() != recorded["sha256"]:
        problems.append(f"{name}: not the {recorded['bytes']} bytes report.json records")
n = report["params"]["n"]
rows = (out / "particles.particles").read_text().splitlines()
if len(rows) != n:
    problems.append(f"particles.particles: {len(rows)} lines for n = {n}")
for number, row in enumerate(rows, 1):
    values = row.split()
    if len(values) != 3 or not all(math.isfinite(float(v)) for v in values):
        problems.append(f"particles.particles line {number} is not three finite numbers: {row!r}")
        break
csv = (out / "particles.csv").read_text().splitlines()
if len(csv) != n + 1 or not csv[0].startswith("particle,vertex,x,y,z"):
    problems.append(f"particles.csv: {len(csv)} lines for n = {n} and a header")
for check in checks:
    path, operator, wanted = re.fullmatch(r"([^=>~]+)([=>~])(.*)", check).groups()
    value = report
    for key in path.split("."):
        value = value.get(key) if isinstance(value, dict) else None
    if operator == "=":
        try:
            expected = json.loads(wanted)
        except ValueError:
            expected = wanted
        ok = value == expected
    elif operator == ">":
        ok = isinstance(value, (int, float)) and value > float(wanted)
    else:
        ok = wanted in json.dumps(value)
    if not ok:
        problems.append(f"report.json {path} is {json.dumps(value)}, expected {operator}{wanted}")
for problem in problems:
    print("FAIL:", problem)
if not problems:
    print(f"ok: {out} holds the run's {len(report['outputs']) + 1} files, n = {n}, {' '.join(checks)}")
sys.exit(1 if problems else 0)
PY
