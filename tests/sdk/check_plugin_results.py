"""Checks the example plug-in's run (tests/sdk/example_plugin_test.cmake): every surface measure
ran on `flat` with status ok and real figures."""
import json
import sys


def fail(message):
    print("check_plugin_results: " + message)
    sys.exit(1)


results = json.load(open(sys.argv[1]))
records = [r for r in results["records"] if r["technique"] == "flat"]
if not records:
    fail("no record of the technique 'flat'")
measures = {}
for record in records:
    for measure in record["measures"]:
        if measure["status"] != "ok":
            fail(f"{measure['measure']}: status {measure['status']}: {measure['reason']}")
        measures[measure["measure"]] = measure


def rows(measure_id):
    if measure_id not in measures:
        fail(f"measure {measure_id} did not run (ran: {sorted(measures)})")
    # results.json schema 4: "keys" and "metrics" name the columns once; a row is
    # [[key values], [metric values]] (null when absent), then status and reason when not ok.
    measure = measures[measure_id]
    objects = []
    for line in measure["rows"]:
        row = {"keys": {k: v for k, v in zip(measure["keys"], line[0]) if v is not None},
               "metrics": {m: v for m, v in zip(measure["metrics"], line[1]) if v is not None}}
        if len(line) == 4:
            row["status"], row["reason"] = line[2], line[3]
        objects.append(row)
    return objects


def metric(row, name):
    if name in row["metrics"]:
        return row["metrics"][name]
    fail(f"row {row['keys']} has no {name}")


# Error against the limit surface: measured, finite and non-zero (flat triangles are not the limit).
error = rows("error")[0]
if not 0 < metric(error, "parametric_max") < 1:
    fail(f"error parametric_max {metric(error, 'parametric_max')}")
# Cracks: every measured row, CPU twin and GPU alike, has 0 unequal shared points.
measured_gpu = 0
for row in rows("cracks"):
    if row.get("status", "ok") != "ok":
        fail(f"cracks row {row['keys']}: {row.get('status')}: {row.get('reason')}")
    if metric(row, "points_not_equal") != 0 or metric(row, "unpaired_points") != 0:
        fail(f"cracks row {row['keys']}: unequal shared points")
    measured_gpu += row["keys"]["backend"] == "gpu"
if measured_gpu == 0:
    fail("no GPU crack row: the plug-in's shaders did not run")
# Instructions: both shipped shaders counted, and the exact operation counts.
stages = {row["keys"].get("stage") for row in rows("instructions")}
for stage in ("flat/flat.tesc", "flat/flat.tese", "per_vertex"):
    if stage not in stages:
        fail(f"instructions: no row for {stage} (rows: {sorted(s for s in stages if s)})")
# Memory: the plain mesh's own footprint against itself.
memory = rows("memory")[0]
if metric(memory, "plain_bytes") <= 0:
    fail("memory: no plain_bytes")
print(f"check_plugin_results: ok ({len(records)} records; measures {sorted(measures)})")
