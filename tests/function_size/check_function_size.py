#!/usr/bin/env python3
"""No function in src/ over the limit (80 lines, signature to closing brace).

The sources are clang-formatted (.clang-format): a function defined at namespace scope
starts at column 0 and its body ends at the next line that is exactly "}"; a member
function defined in its class is indented and ends at the "}" of its own indentation.
Usage: check_function_size.py ROOT [LIMIT]. Prints each function over the limit as
path:line: N lines, and exits 1 if there is one."""
import pathlib
import re
import sys

SKIP = re.compile(r"^\s*(namespace|class|struct|union|enum|extern|#|//|using|typedef|template\b|\}|\{|static_assert)")


def functions(lines):
    """(first line, last line) of each function body that opens with '{' at the end of a line."""
    i = 0
    while i < len(lines):
        line = lines[i]
        indent = len(line) - len(line.lstrip(" "))
        if line.strip() and not SKIP.match(line) and "(" in line and indent <= 4:
            # the signature may span lines: find the line that ends it with '{'
            j = i
            while j < len(lines) and j < i + 8:
                s = lines[j].rstrip()
                if s.endswith(";") or (s.endswith("}") and "{" in s):
                    break
                if s.endswith("{"):
                    close = " " * indent + "}"
                    k = j + 1
                    while k < len(lines) and lines[k].rstrip() not in (close, close + ";"):
                        k += 1
                    if k < len(lines):
                        yield i, k
                        i = k
                    break
                j += 1
        i += 1


def main():
    root = pathlib.Path(sys.argv[1])
    limit = int(sys.argv[2]) if len(sys.argv) > 2 else 80
    over = []
    for path in sorted((root / "src").rglob("*")):
        if path.suffix not in (".cpp", ".h"):
            continue
        lines = path.read_text(encoding="utf-8").splitlines()
        for first, last in functions(lines):
            n = last - first + 1
            if n > limit:
                over.append(f"{path.relative_to(root)}:{first + 1}: {n} lines (limit {limit})")
    for o in over:
        print(o)
    if over:
        print(f"{len(over)} function(s) over {limit} lines: split them into named steps")
        return 1
    print(f"no function in src/ over {limit} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
