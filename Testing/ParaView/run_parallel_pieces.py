"""Runs parallel_pieces.py on 2 MPI ranks with pvbatch and fails unless both ranks passed.

Usage: run_parallel_pieces.py MPIEXEC PVBATCH SCRIPT PLUGIN PYTHONPATH MESH_DIR
The exit status alone is not trusted (a pvbatch that swallows the script's exception
exits 0): each rank must also print its "checks passed" line.
"""
import os
import re
import subprocess
import sys

mpiexec, pvbatch, script, *arguments = sys.argv[1:]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
run = subprocess.run([mpiexec, "--oversubscribe", "-n", "2", pvbatch, "--mpi", "--symmetric", script, *arguments],
                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=environment,
                     timeout=600)
print(run.stdout)
passed = {int(rank) for rank in re.findall(r"parallel_pieces: rank (\d+): \d+ checks passed", run.stdout)}
if run.returncode != 0 or passed != {0, 1}:
    sys.exit(f"run_parallel_pieces: exit status {run.returncode}, ranks that passed: {sorted(passed)}")
print("run_parallel_pieces: both ranks passed")
