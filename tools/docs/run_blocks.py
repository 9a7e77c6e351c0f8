#!/usr/bin/env python3
"""Runs the examples of the README and the manual that are marked runnable, so that a
renamed command, option or output file fails a test instead of a reader.

    run_blocks.py [--stage DIR] [--only TEXT] FILE.md ...

A block is runnable when the line before its opening fence is the HTML comment
``<!-- run -->`` (invisible on GitHub and in the built manual)::

    <!-- run -->
    ```sh
    flowsurf render builtin:tori --size 160x120 -o tori.png
    ```

``sh``/``bash`` blocks run in bash with -e -o pipefail, ``python`` blocks in python3. The
blocks of one page run in order in one fresh folder, with `flowsurf` on PATH and the
module on PYTHONPATH (FLOWSURF_BIN, FLOWSURF_PYTHONPATH). A block fails when it exits
non-zero or when a file it names as output (``-o F``, ``--output F``, ``--flow-texture F``,
``--quality F``, ``.save("F")``; a ``%04d`` pattern: its first frame) is missing or empty
afterwards, unless the block itself checks that F is not made (``test ! -e F``). The page's images (``![...](PATH)``) made by its blocks are copied into
``--stage DIR`` beside the staged page, so the gallery shows what its commands made.
Relative links and images of each page must exist (in the stage or beside the file).
Prints one line per block and closes with ``N passed, N failed``.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARK = re.compile(r"^<!--\s*run\s*-->\s*$")
FENCE = re.compile(r"^```\s*([A-Za-z0-9_+-]*)")
OUTPUTS = [re.compile(p) for p in (r"(?:^|\s)-o\s+(\S+)", r"--output[ =](\S+)", r"--flow-texture[ =](\S+)",
                                    r"--quality[ =](\S+)", r"\.save\(\s*f?[\"']([^\"']+)[\"']")]
ALT = r"\[(?:[^\[\]]|\[[^\]]*\])*\]"  # link text, one level of [brackets] inside
IMAGE = re.compile(r"!" + ALT + r"\(([^)\s]+)")
LINK = re.compile(r"(?<!!)" + ALT + r"\(([^)\s]+)\)")
TIMEOUT_S = 300


def blocks(path):
    """(line, language, code) of every runnable block of a Markdown file."""
    out, lines = [], open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        if MARK.match(lines[i]) and i + 1 < len(lines) and FENCE.match(lines[i + 1]):
            lang = FENCE.match(lines[i + 1]).group(1).lower()
            j = i + 2
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            if j == len(lines):
                raise SystemExit(f"{path}:{i + 2}: runnable block without a closing fence")
            if lang not in ("sh", "bash", "python"):
                raise SystemExit(f"{path}:{i + 2}: runnable block in '{lang}': only sh, bash and python run")
            out.append((i + 2, lang, "\n".join(lines[i + 2:j]) + "\n"))
            i = j
        i += 1
    return out


def outputs(code):
    names = []
    for line in code.split("\n"):
        line = line.split(" #")[0]
        for pattern in OUTPUTS:
            names += [m.group(1).strip("'\"") for m in pattern.finditer(line)]
    absent = set(re.findall(r"!\s+-e\s+(\S+)", code))  # `test ! -e F`: the block checks F is not made
    return [n for n in names if "{" not in n and "$" not in n and n not in absent]


def expected_file(work, name):
    name = re.sub(r"%0?(\d*)d", lambda m: "0" * max(int(m.group(1) or 1), 1), name)
    return os.path.join(work, name)


def run_block(lang, code, work, env):
    if lang == "python":
        cmd = [env.get("FLOWSURF_PYTHON", sys.executable), "-c", code]
    else:
        cmd = ["bash", "-e", "-o", "pipefail", "-c", code]
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=TIMEOUT_S, text=True)
        rc, log = p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        rc, log = 124, (e.stdout or b"").decode(errors="replace") + f"\n(timed out after {TIMEOUT_S} s)"
    return rc, log, time.time() - t0


def check_links(path, text, stage_dir):
    """Relative links and images that point nowhere, in the stage or beside the source."""
    bad = []
    base = os.path.dirname(os.path.abspath(path))
    for m in list(LINK.finditer(text)) + list(IMAGE.finditer(text)):
        target = m.group(1).split("#")[0]
        if not target or re.match(r"^[a-z]+:", target):
            continue
        if not any(os.path.exists(os.path.join(d, target)) for d in (base, stage_dir) if d):
            bad.append(target)
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stage", help="staged docs folder: images the blocks make are copied there")
    ap.add_argument("--only", help="run only the pages whose path contains this text")
    ap.add_argument("--no-links", action="store_true", help="skip the link check (the stage is not complete)")
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    env = dict(os.environ)
    if env.get("FLOWSURF_BIN"):
        env["PATH"] = env["FLOWSURF_BIN"] + os.pathsep + env["PATH"]
    if env.get("FLOWSURF_PYTHONPATH"):
        env["PYTHONPATH"] = env["FLOWSURF_PYTHONPATH"] + os.pathsep + env.get("PYTHONPATH", "")
    env.setdefault("MPLBACKEND", "Agg")
    passed = failed = 0
    for path in args.files:
        if args.only and args.only not in path:
            continue
        text = open(path, encoding="utf-8").read()
        stage_dir = None
        if args.stage:
            rel = os.path.relpath(os.path.abspath(path), os.path.abspath(args.stage))
            stage_dir = os.path.dirname(os.path.join(args.stage, rel)) if not rel.startswith("..") else args.stage
        found = blocks(path)
        work = tempfile.mkdtemp(prefix="flowsurf-docs-")
        try:
            for line, lang, code in found:
                rc, log, secs = run_block(lang, code, work, env)
                missing = [n for n in outputs(code) if not (os.path.isfile(expected_file(work, n))
                                                             and os.path.getsize(expected_file(work, n)) > 0)]
                where = f"{path}:{line}"
                if rc == 0 and not missing:
                    passed += 1
                    print(f"ok   {where} ({lang}, {secs:.1f} s)", flush=True)
                else:
                    failed += 1
                    why = f"exit {rc}" if rc else "no output file " + ", ".join(missing)
                    print(f"FAIL {where} ({lang}): {why}\n--- block:\n{code}--- output:\n{log[-4000:]}", flush=True)
            if stage_dir:
                for target in IMAGE.findall(text):
                    made = os.path.join(work, target)
                    if not re.match(r"^[a-z]+:", target) and os.path.isfile(made):
                        dest = os.path.join(stage_dir, target)
                        os.makedirs(os.path.dirname(dest), exist_ok=True)
                        shutil.copyfile(made, dest)
            if not args.no_links:
                for target in check_links(path, text, stage_dir):
                    failed += 1
                    print(f"FAIL {path}: link or image '{target}' points nowhere", flush=True)
        finally:
            shutil.rmtree(work, ignore_errors=True)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
