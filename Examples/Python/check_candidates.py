"""Registers SOURCE onto TARGET, says how sure the refinement is of the map it kept, and, when
another candidate's map came close, writes that one too so that the two can be compared (in
ParaView, side by side) and the right one kept.

The refinement starts ZoomOut from every candidate rotation of the Möbius stage and keeps
the map of the expected orientation whose images keep the surfaces' smoothed mean curvature
best; when the runner-up comes within 10%, both maps are finished and the one with the
lower product of curvature difference and mean edge stretch is kept (field data
CandidateMapStretch: the finished maps' stretch; RefinementConfidence: the kept map's score
by what decided, the runner-up and the margin to it; -1 for a margin without bound, when
the kept map's score is 0). A human body turned half a turn about its vertical axis is
nearly an isometry of the body, so on a hard pair two candidates can come close; a margin
below 5% is flagged (mobius-register warns too). Keep the other with `candidate=` here, or
with `mobius-register --candidate K`, or the Candidate property of Refine Correspondence in
ParaView.

Usage: python3 check_candidates.py SOURCE TARGET --output DIR [--candidate K]
Writes DIR/kept.vtp (and DIR/runner-up.vtp when there is a runner-up) and DIR/candidates.csv.
"""
import argparse
import csv
import os

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

import mobiusregistration

NEAR_EQUAL = 0.05  # the margin below which the refinement calls two candidates near-equal


def write(registration, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(registration.polydata)
    writer.SetDataModeToBinary()  # bookworm's expat cannot read VTK 9.2's appended data back
    if not writer.Write():
        raise SystemExit(f"cannot write {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("--output", required=True)
    parser.add_argument("--candidate", type=int, default=None,
                        help="keep this candidate's map instead of the one the refinement chooses")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    kept = mobiusregistration.register(args.source, args.target, candidate=args.candidate)
    fields = kept.fields
    score, runner_up, margin = [float(v) for v in fields["RefinementConfidence"].ravel()]
    chosen = int(fields["RefinementCandidate"])
    # Finished maps have a stretch (-1 for the others): two finished maps were compared by
    # their curvature difference times their stretch.
    stretches = [float(v) for v in fields["CandidateMapStretch"].ravel()]
    by_stretch = sum(v >= 0 for v in stretches) == 2
    write(kept, os.path.join(args.output, "kept.vtp"))
    with open(os.path.join(args.output, "candidates.csv"), "w", newline="") as table:
        rows = csv.writer(table)
        rows.writerow(["candidate", "kept", "curvature_difference", "map_stretch",
                       "orientation_agreement", "orthogonality_residual"])
        for c, difference in enumerate(fields["CandidateCurvatureDifferences"].ravel()):
            stretch = stretches[c]
            rows.writerow([c, int(c == chosen), difference, stretch if stretch >= 0 else "",
                           fields["CandidateOrientationAgreement"][c],
                           fields["CandidateOrthogonalityResiduals"][c]])
    decided = "curvature and map stretch" if by_stretch else "curvature"
    if args.candidate is not None:
        decided = "given"
    print(f"kept candidate {chosen} by {decided}: score {score:.4g}, "
          f"mean edge stretch {fields['RefinementMeanStretch']:.3g}")
    if runner_up < 0:
        print("no other candidate gave a different map of the right orientation")
        return
    runner_up = int(runner_up)
    if margin < 0:  # the kept map scores 0: no other can come near
        print(f"runner-up: candidate {runner_up}, far behind (the kept map's score is 0)")
    else:
        print(f"runner-up: candidate {runner_up}, margin {100 * margin:.1f}%"
              + (" (near-equal: check the map)" if margin < NEAR_EQUAL else ""))
    other = mobiusregistration.register(args.source, args.target, candidate=runner_up)
    write(other, os.path.join(args.output, "runner-up.vtp"))
    print(f"wrote {args.output}/kept.vtp and runner-up.vtp: open both in ParaView, color them "
          f"by MapStretch or by a target array, and keep the right one with --candidate")


if __name__ == "__main__":
    main()
