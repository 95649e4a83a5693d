"""Checks batch_register.py's summary.csv from its test (run with --no-repair): the template
registered to itself with no rotation and no error, the genus-2 mesh failed with the filter's
reason, naming it, and the other mesh registered, its map written."""
import csv
import os
import sys

with open(os.path.join(sys.argv[1], "summary.csv"), newline="") as f:
    rows = {os.path.basename(row["mesh"]): row for row in csv.DictReader(f)}
failures = []
hand, eight, cow = rows.get("hand.off"), rows.get("eight.off"), rows.get("cow.off")
if not hand or hand["status"] != "ok" or float(hand["registration_error"]) > 1e-9 \
        or float(hand["rotation_degrees"]) > 1e-3:
    failures.append(f"the template onto itself: {hand}")
if not eight or eight["status"] != "failed" or "eight.off" not in eight["output_or_error"] \
        or "genus 2" not in eight["output_or_error"]:
    failures.append(f"the genus-2 mesh: {eight}")
if not cow or cow["status"] != "ok" or not os.path.getsize(cow["output_or_error"]):
    failures.append(f"the cow: {cow}")
for failure in failures:
    print("FAILED:", failure)
print(f"{len(rows)} rows checked" if not failures else f"{len(failures)} rows wrong")
sys.exit(1 if failures else 0)
