#!/usr/bin/env python3
"""Makes an installed flowsurf tree self-contained, and checks that it is.

    portable_tree.py bundle TREE   copy every shared library the tree's programs and libraries
                                   need into TREE/lib (except the system's, below), strip them,
                                   give every ELF file an $ORIGIN-relative RUNPATH, and write
                                   TREE/share/doc/flowsurf/bundled.txt with the licences
    portable_tree.py check TREE    fail unless every ELF file's RUNPATH stays inside TREE and
                                   every library it needs that is not the system's resolves
                                   inside TREE, both as the loader searches (readelf) and as it
                                   really does (ldd, no LD_LIBRARY_PATH)

Dependencies are walked from the real ones: ldd for the resolved closure, readelf for each
file's NEEDED and RUNPATH. Not bundled (SYSTEM): the C library (its parts use each other's
private symbols, so they must come from one build), the compiler runtime libstdc++/libgcc_s
(every system with this glibc has a newer or equal one, and the GL driver loads the system's
into the same process: two copies conflict, an older bundled one breaks a newer driver), and
the GL/EGL driver stack (glvnd's loaders and whatever vendor driver they pick).
Needs: python3, binutils (readelf, strip), patchelf, dpkg (licences).
"""
import os
import re
import shutil
import subprocess
import sys

# Sonames never bundled; see the docstring for why each group.
SYSTEM = [
    # glibc
    r"linux-vdso\.so\.1", r"ld-linux-x86-64\.so\.2", r"libc\.so\.6", r"libm\.so\.6", r"libdl\.so\.2",
    r"libpthread\.so\.0", r"librt\.so\.1", r"libresolv\.so\.2", r"libutil\.so\.1", r"libanl\.so\.1",
    r"libmvec\.so\.1", r"libBrokenLocale\.so\.1", r"libnsl\.so\.1", r"libnss_.*", r"libthread_db\.so\.1",
    r"libc_malloc_debug\.so\.0",
    # compiler runtime
    r"libstdc\+\+\.so\.6", r"libgcc_s\.so\.1",
    # GL/EGL: glvnd's loaders and the drivers behind them
    r"libEGL\.so\.1", r"libGL\.so\.1", r"libOpenGL\.so\.0", r"libGLdispatch\.so\.0", r"libGLX\.so\.0",
    r"libGLESv1_CM\.so\.1", r"libGLESv2\.so\.2", r"libEGL_.*", r"libGLX_.*", r"libgbm\.so\..*",
    r"libglapi\.so\..*", r"libdrm.*", r"libnvidia-.*",
]
_SYSTEM_RE = re.compile("^(" + "|".join(SYSTEM) + ")$")


def is_system(soname):
    return bool(_SYSTEM_RE.match(os.path.basename(soname)))


def run(*cmd, env=None):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout


def is_elf(path):
    if os.path.islink(path) or not os.path.isfile(path):
        return False
    with open(path, "rb") as f:
        return f.read(4) == b"\x7fELF"


def elf_files(tree):
    """Every ELF file in TREE (symlinks not followed), sorted."""
    out = []
    for root, _, files in os.walk(tree):
        out += [os.path.join(root, f) for f in files if is_elf(os.path.join(root, f))]
    return sorted(out)


def dynamic(path):
    """(NEEDED list, RPATH list, RUNPATH list) from readelf -d."""
    needed, rpath, runpath = [], [], []
    for line in run("readelf", "-dW", path).splitlines():
        m = re.search(r"\((NEEDED|RPATH|RUNPATH)\)\s+\S+.*?\[(.*)\]", line)
        if not m:
            continue
        kind, value = m.groups()
        if kind == "NEEDED":
            needed.append(value)
        else:
            (rpath if kind == "RPATH" else runpath).extend(v for v in value.split(":") if v)
    return needed, rpath, runpath


def ldd(path):
    """soname -> resolved path (None where 'not found'), as the real loader resolves it."""
    env = {k: v for k, v in os.environ.items() if k != "LD_LIBRARY_PATH"}
    out = {}
    for line in run("ldd", path, env=env).splitlines():
        m = re.match(r"\s*(\S+)\s+=>\s+(not found|(\S+))", line)
        if m:
            out[m.group(1)] = None if m.group(2) == "not found" else m.group(3)
    return out


def lib_dir(tree):
    return os.path.join(tree, "lib")


def origin_runpath(tree, elf):
    return "$ORIGIN/" + os.path.relpath(lib_dir(tree), os.path.dirname(elf)) if \
        os.path.dirname(elf) != lib_dir(tree) else "$ORIGIN"


def owner_packages(paths):
    """path -> the Debian package that installed it, in one dpkg -S (usrmerge: a file under
    /usr/lib may be registered as /lib, and the other way round)."""
    spellings = {}
    for path in paths:
        for p in {path, os.path.realpath(path)}:
            for q in (p, p[4:] if p.startswith("/usr/") else "/usr" + p):
                spellings[q] = path
    r = subprocess.run(["dpkg", "-S"] + sorted(spellings), capture_output=True, text=True)
    owners = {}
    for line in r.stdout.splitlines():
        pkg, _, file = line.partition(": ")
        if file in spellings and "," not in pkg:
            owners[spellings[file]] = pkg.split(":")[0]
    for path in paths:
        if path not in owners:
            raise SystemExit(f"portable_tree: no Debian package owns {path}: cannot find its licence")
    return owners


def bundle(tree):
    tree = os.path.abspath(tree)
    os.makedirs(lib_dir(tree), exist_ok=True)
    ours = elf_files(tree)
    # The closure as the build machine's loader resolves it, for each of our files.
    wanted = {}
    for f in ours:
        for soname, path in ldd(f).items():
            if is_system(soname) or (path and path.startswith(tree + "/")):
                continue
            if path is None:
                raise SystemExit(f"portable_tree: {f} needs {soname}, which this machine does not have")
            wanted[soname] = path
    for soname, path in sorted(wanted.items()):
        dst = os.path.join(lib_dir(tree), soname)
        shutil.copyfile(path, dst)
        os.chmod(dst, 0o755)
        subprocess.run(["strip", "--strip-unneeded", dst], check=True)
    # Every ELF file (ours and the copies) searches TREE/lib first, wherever TREE is.
    for f in elf_files(tree):
        subprocess.run(["patchelf", "--set-rpath", origin_runpath(tree, f), f], check=True)
    write_licences(tree, wanted)
    return wanted


def write_licences(tree, wanted):
    doc = os.path.join(tree, "share/doc/flowsurf")
    lic = os.path.join(doc, "licenses")
    os.makedirs(lic, exist_ok=True)
    owners = owner_packages(list(wanted.values()))
    names = sorted(set(owners.values()) | set(extra_packages(tree)))
    versions = dict(line.split(" ", 1) for line in
                    run("dpkg-query", "-W", "-f=${Package} ${Version}\n", *names).splitlines())
    rows = [f"{soname}\t{owners[path]}\t{versions[owners[path]]}" for soname, path in sorted(wanted.items())]
    packages = {name: versions[name] for name in names}
    for pkg in sorted(packages):
        src = f"/usr/share/doc/{pkg}/copyright"
        if not os.path.exists(src):
            raise SystemExit(f"portable_tree: {src} missing: the licence of {pkg} cannot be shipped")
        shutil.copyfile(src, os.path.join(lic, pkg + ".copyright"))
    with open(os.path.join(doc, "bundled.txt"), "w") as f:
        f.write("# Shared libraries in lib/ (soname, Debian 12 package, version); licences in licenses/\n")
        f.write("\n".join(rows) + "\n")


def extra_packages(tree):
    """Packages of bundled files that are not libraries (the label font)."""
    return ["fonts-dejavu-core"] if os.path.isdir(os.path.join(tree, "share/flowsurf/fonts")) else []


def check(tree):
    """Returns a list of problems (empty: the tree is self-contained)."""
    tree = os.path.abspath(tree)
    problems = []
    files = elf_files(tree)
    if not files:
        return [f"{tree}: no ELF files"]
    for f in files:
        rel = os.path.relpath(f, tree)
        needed, rpath, runpath = dynamic(f)
        if rpath:
            problems.append(f"{rel}: has DT_RPATH {':'.join(rpath)} (only $ORIGIN RUNPATHs)")
        dirs = []
        for entry in runpath:
            if not entry.startswith("$ORIGIN"):
                problems.append(f"{rel}: RUNPATH entry {entry} is not $ORIGIN-relative")
                continue
            d = os.path.normpath(entry.replace("$ORIGIN", os.path.dirname(f), 1))
            if d != tree and not d.startswith(tree + "/"):
                problems.append(f"{rel}: RUNPATH entry {entry} leaves the tree")
                continue
            dirs.append(d)
        # The loader's search for this file's own NEEDED: its RUNPATH dirs.
        for soname in needed:
            if is_system(soname):
                continue
            if not any(os.path.exists(os.path.join(d, soname)) for d in dirs):
                problems.append(f"{rel}: needs {soname}, not found through its RUNPATH inside the tree")
        # The real loader, for the whole closure.
        for soname, path in ldd(f).items():
            if is_system(soname):
                continue
            if path is None:
                problems.append(f"{rel}: ldd: {soname} not found")
            elif not os.path.realpath(path).startswith(tree + "/"):
                problems.append(f"{rel}: ldd: {soname} resolves outside the tree ({path})")
    return problems


def main(argv):
    if len(argv) != 3 or argv[1] not in ("bundle", "check"):
        print(__doc__.split("\n\n")[0], file=sys.stderr)
        return 2
    if argv[1] == "bundle":
        wanted = bundle(argv[2])
        print(f"portable_tree: bundled {len(wanted)} libraries into {os.path.join(argv[2], 'lib')}")
        return 0
    problems = check(argv[2])
    for p in problems:
        print("portable_tree: " + p, file=sys.stderr)
    print(f"portable_tree: {len(elf_files(argv[2]))} ELF files, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
