#!/usr/bin/env python3
"""Checks that every `#include "..."` of the sources runs down the layers that
doc/architecture.md draws (its ```layers block: `folder: the folders it builds on`, the
lowest first; what a folder builds on, it may include, and what those build on). Every
target exports src/ as its include root, so the include paths alone cannot stop a lower
folder from including a higher one: this test does. GLSL includes are held to the same
table, shaders/NAME standing for the folder of the table whose last part is NAME.

  check_layers.py ROOT            exit 1 naming each include that goes up or sideways
  check_layers.py ROOT --graph    print the folder graph the includes draw
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SOURCES = ('.h', '.hpp', '.cpp', '.cxx', '.cc', '.c', '.glsl', '.vert', '.frag', '.comp', '.geom')
SCANNED = ('src', 'apps', 'bench', 'python', 'tests', 'fuzz', 'tools', 'include', 'examples', 'shaders')


def read_table(root):
    text = open(os.path.join(root, 'doc', 'architecture.md'), encoding='utf-8').read()
    m = re.search(r'^```layers\n(.*?)^```', text, re.M | re.S)
    if not m:
        sys.exit('check_layers: doc/architecture.md has no ```layers block')
    table = {}
    for n, line in enumerate(m.group(1).splitlines(), 1):
        line = line.split('#', 1)[0].strip()
        if not line:
            continue
        name, _, below = line.partition(':')
        name = name.strip()
        if name in table:
            sys.exit(f'check_layers: the layers block names {name} twice')
        for b in below.split():
            if b != '*' and b not in table:
                sys.exit(f'check_layers: layers line {n}: {name} builds on {b}, which is not named above it')
        table[name] = below.split()
    return table


def closure(table):
    below = {}
    for name, direct in table.items():  # the block lists the lowest first
        s = set()
        for d in direct:
            s |= {'*'} if d == '*' else {d} | below[d]
        below[name] = s
    return below


def unit_of(path, units, shader_units):
    if path.startswith('shaders/'):
        parts = path.split('/')
        return shader_units.get(parts[1]) if len(parts) > 2 else None
    best = None
    for u in units:
        # a folder, or one file pair of a folder (src/methods/make_renderer.h and .cpp)
        if (path.startswith(u + '/') or os.path.splitext(path)[0] == u) and (best is None or len(u) > len(best)):
            best = u
    return best


def resolve(root, path, inc):
    here = os.path.dirname(path)
    bases = ['shaders'] if path.startswith('shaders/') else [here, 'src', 'include', '.']
    for b in bases:
        cand = os.path.normpath(os.path.join(b, inc))
        if os.path.isfile(os.path.join(root, cand)):
            return cand
    return None  # generated, or outside the repository


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else '.')
    table = read_table(root)
    below = closure(table)
    shader_units = {u.rsplit('/', 1)[-1]: u for u in table}
    graph, bad = {}, []
    for top in SCANNED:
        for d, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(x for x in dirs if not x.startswith('.') and x != 'build')
            for f in sorted(files):
                if not f.endswith(SOURCES):
                    continue
                path = os.path.relpath(os.path.join(d, f), root)
                u = unit_of(path, table, shader_units)
                try:
                    text = open(os.path.join(root, path), encoding='utf-8').read()
                except UnicodeDecodeError:
                    continue
                for m in INCLUDE.finditer(text):
                    target = resolve(root, path, m.group(1))
                    v = target and unit_of(target, table, shader_units)
                    if not v or v == u:
                        continue
                    if u is None:
                        bad.append(f'{path}: in no folder of the layers block (includes {m.group(1)})')
                        continue
                    graph.setdefault(u, set()).add(v)
                    if '*' not in below[u] and v not in below[u]:
                        line = text.count('\n', 0, m.start()) + 1
                        bad.append(f'{path}:{line}: {u} includes "{m.group(1)}" of {v}, '
                                   f'which {u} does not build on (doc/architecture.md, layers)')
    if '--graph' in sys.argv:
        for u in table:
            print(f'{u}: {" ".join(sorted(graph.get(u, ())))}')
        return 0
    for b in bad:
        print(b)
    print(f'check_layers: {len(bad)} include(s) against the layers' if bad else 'check_layers: every include runs down the layers')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
