"""Runs the code blocks of README.md and of the pages in docs/ as a user would, from a folder where `build` is the build
tree: blocks tagged `sh` with bash, `python` with Debian's python3 (the package folder on
PYTHONPATH, as the Python page says), `pvpython` with pvpython. Blocks tagged `shell` (the setup
commands, which CI itself runs, and starting the GUI) and `c++` (a fragment) are not run.

The snippets' paths are those of the default build (`lib` for the libdir); a build for the
/usr prefix (the .deb's) puts the plugin under lib/x86_64-linux-gnu, so the plugin paths
are read in that build's libdir (the fourth argument).
Usage: test_readme_snippets.py BUILD PVPYTHON WORK LIBDIR FILE_OR_FOLDER... (a folder: its *.md)"""
import os
import glob
import re
import shutil
import subprocess
import sys

build, pvpython, work, libdir = sys.argv[1:5]
documents = []
for path in sys.argv[5:]:
    documents += sorted(glob.glob(os.path.join(path, "*.md"))) if os.path.isdir(path) else [path]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.symlink(build, os.path.join(work, "build"))

blocks = []
for document in documents:
    text = open(document, encoding="utf-8").read()
    name = os.path.basename(document)
    blocks += [(name, language, code)
               for language, code in re.findall(r"^```(\S*)\n(.*?)^```", text, flags=re.M | re.S)]
runners = {
    "sh": ["bash", "-e"],
    "python": ["/usr/bin/python3"],
    "pvpython": [pvpython, "--force-offscreen-rendering"],
}
env = dict(os.environ, PYTHONPATH=os.path.join(build, "lib/python3/dist-packages"))
failures, ran = 0, 0
for number, (document, language, code) in enumerate(blocks):
    if language not in runners:
        continue
    script = os.path.join(work, f"snippet{number}.{language}")
    with open(script, "w") as f:
        f.write(code.replace("build/lib/paraview-5.11/", f"build/{libdir}/paraview-5.11/"))
    result = subprocess.run(runners[language] + [script], cwd=work, env=env, capture_output=True, text=True)
    ran += 1
    status = "ok" if result.returncode == 0 else f"FAILED ({result.returncode})"
    print(f"block {number} ({document}, {language}): {status}")
    if result.returncode != 0:
        failures += 1
        print(code, result.stdout[-2000:], result.stderr[-2000:], sep="\n")
print(f"{ran - failures} passed, {failures} failed")
sys.exit(1 if failures or ran < 3 else 0)
