#!/usr/bin/env bash
# Plans, compares and exports the bundled samples with one spira-cli and prints a SHA-256 per output file,
# so that two builds (before and after a refactoring that must not change results) can be diffed:
#   bench/golden_outputs.sh OLD/spira-cli [KEEP_DIR] > old.txt; bench/golden_outputs.sh NEW/spira-cli > new.txt; diff old.txt new.txt
set -u
cli=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
if [ $# -ge 2 ]; then # keep the outputs in $2 for a closer look
  work=$(realpath -m "$2")
  rm -rf "$work" && mkdir -p "$work"
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/spira-golden.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
samples="$root/resources/samples"
cells="$root/resources/cells"
run() { # name, args...
  local name=$1
  shift
  (cd "$work" && "$cli" "$@" > "$work/$name.stdout" 2> "$work/$name.stderr")
  echo "$name exit $?"
}
for part in dome cone open_cylinder; do
  run "$part-plain" plan "$samples/$part.stl" -o "$work/$part-plain"
  run "$part-fanuc" plan "$samples/$part.stl" --cell "$cells/fanuc_m20ia_positioner.cell" --export fanuc_tp -o "$work/$part-fanuc"
  run "$part-kuka" plan "$samples/$part.stl" --cell "$cells/kuka_kr16_2_table.cell" --export krl -o "$work/$part-kuka"
  run "$part-krl-export" export "$work/$part-plain" --format krl -o "$work/$part-krl-export"
done
run dome-compare compare "$samples/dome.stl" -o "$work/dome-compare"
# Timings, dates and absolute paths differ from run to run and are masked; strategy names are written in the
# short form since the pipeline redesign and are compared in that form. Everything else is compared byte for byte.
python3 - "$work" "$root" <<'PY'
import hashlib, json, os, re, sys
work, root = sys.argv[1], sys.argv[2]
dated = ("report.json", "spira_part.src", "SPIRA_PART.ls")  # their .spira-set.json hashes cover timings or dates
# Keys report.json gained in the pipeline redesign (issue 16): the spiral's window and the motion's wall time.
added = ("h", "h_min", "h_max", "height_tolerance_mm", "collapsed_revolutions", "seconds")
def scrub(v):
    if isinstance(v, dict):
        return {k: scrub(x) for k, x in v.items()
                if not k.endswith("timings_s") and k not in ("runtime_s", "seconds", "elapsed_s")
                and not (k in ("fnv1a64", "size") and v.get("name") in dated)}
    if isinstance(v, list):
        return [scrub(x) for x in v]
    if isinstance(v, str):
        return re.sub(r"^decomposer\.", "", v.replace(work, "WORK").replace(root, "ROOT"))
    return v
for dirpath, _, names in sorted(os.walk(work)):
    for name in sorted(names):
        if name.endswith((".stdout", ".stderr", ".png")):
            continue
        path = os.path.join(dirpath, name)
        data = open(path, "rb").read()
        if name.endswith(".json"):
            j = scrub(json.loads(data))
            if name == "report.json":
                j = {k: v for k, v in j.items() if k not in added}
            data = json.dumps(j, sort_keys=True).encode()
        else:
            text = data.decode("latin-1").replace(work, "WORK").replace(root, "ROOT")
            text = re.sub(r"DATE \S+\s+TIME \S+;", "DATE D TIME T;", text)
            text = re.sub(r"\d{4}-\d\d-\d\d \d\d:\d\d( UTC)?", "DATETIME", text)
            text = re.sub(r"(?m)^(\d+,)?decomposer\.", r"\1", text)
            data = text.encode("latin-1")
        print(hashlib.sha256(data).hexdigest(), os.path.relpath(path, work))
PY
