#!/usr/bin/env bash
# Builds the manual (MkDocs, strict) from docs/ into BUILD/site, after a build of flowsurf:
#   scripts/docs.sh [BUILD_DIR]          (default build/; run scripts/build.sh first)
# 1. stages docs/ in BUILD/docs-src with what lives elsewhere: doc/algorithms.md,
#    doc/architecture.md, doc/images/, the benchmark tables of doc/bench/ as pages, and the
#    pages other engineers' issues keep in doc/ (contrast, reader sandbox) when present;
# 2. generates the option reference (tools/docs/option_reference.cpp, from the option table)
#    and the C++ and Python API pages (tools/docs/api_reference.py);
# 3. runs every runnable example of README.md and the manual (tools/docs/run_blocks.py),
#    which also makes the gallery's images from the commands shown beneath them, and
#    executes the example notebook (tools/docs/run_notebook.py) into the manual;
# 4. mkdocs build --strict: a broken link, a missing image or page fails.
# ctest `docs` runs this. Needs mkdocs + mkdocs-material (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=$(cd "${1:-build}" && pwd)
STAGE=$BUILD/docs-src
SITE=$BUILD/site
for tool in mkdocs; do command -v $tool >/dev/null || { echo "docs.sh: $tool missing (scripts/install-deps.sh)" >&2; exit 1; }; done
[ -x "$BUILD/tools/docs/flowsurf_option_reference" ] || { echo "docs.sh: build first (scripts/build.sh)" >&2; exit 1; }

# 1. Stage.
rm -rf "$STAGE"
cp -r docs "$STAGE"
cp doc/algorithms.md doc/architecture.md "$STAGE/"
mkdir -p "$STAGE/images" "$STAGE/bench"
cp doc/images/* "$STAGE/images/"
for f in doc/bench/*; do
  name=$(basename "$f")
  case "$name" in
    *.md) cp "$f" "$STAGE/bench/$name" ;;
    *.txt) { echo "# ${name%.txt}"; echo; echo "Written by \`scripts/bench-tables.sh\` (\`doc/bench/$name\`)."; echo
             echo '```text'; cat "$f"; echo '```'; } > "$STAGE/bench/${name%.txt}.md" ;;
  esac
done
python3 - "$STAGE/license.md" <<'PY'   # the licence's text into its page
import sys
page = open(sys.argv[1]).read()
open(sys.argv[1], "w").write(page.replace('--8<-- "LICENSE.txt"', open("LICENSE").read().strip()))
PY
config=$BUILD/mkdocs.yml
sed -e "s|^docs_dir:.*|docs_dir: $STAGE|" -e "s|^  - tools/docs/|  - $ROOT/tools/docs/|" mkdocs.yml > "$config"
for extra in contrast reader_sandbox; do   # user pages kept in doc/ by their issues
  if [ -f "doc/$extra.md" ]; then
    cp "doc/$extra.md" "$STAGE/$extra.md"
    title=$(sed -n '1s/^# *//p' "doc/$extra.md")
    python3 - "$config" "$title" "$extra.md" <<'PY'
import sys
path, title, page = sys.argv[1:]
text = open(path).read()
text = text.replace("      - Troubleshooting: troubleshooting.md\n",
                    f"      - {title or page}: {page}\n      - Troubleshooting: troubleshooting.md\n")
open(path, "w").write(text)
PY
  fi
done

# 2. Generated pages.
"$BUILD/tools/docs/flowsurf_option_reference" > "$STAGE/options.md"
python3 tools/docs/api_reference.py cpp include/flowsurf > "$STAGE/api-cpp.md"
PYTHON=/usr/bin/python3; [ -x "$PYTHON" ] || PYTHON=python3
PYTHONPATH="$BUILD/python" "$PYTHON" tools/docs/api_reference.py python > "$STAGE/api-python.md"

# The example notebook, executed headless into the manual (checked: no error, its pictures).
PYTHONPATH="$BUILD/python" "$PYTHON" tools/docs/run_notebook.py docs/notebooks/flowsurf.ipynb \
  "$STAGE/notebooks/flowsurf.html" 2>&1 | grep -v -e "frozen modules" -e "^0.0"

# 3. Every runnable example; the gallery's images.
export FLOWSURF_BIN=$BUILD/apps FLOWSURF_PYTHONPATH=$BUILD/python FLOWSURF_PYTHON=$PYTHON
"$PYTHON" tools/docs/run_blocks.py --stage "$STAGE" README.md "$STAGE"/*.md

# 4. The site.
rm -rf "$SITE"
mkdocs build --strict -q -f "$config" -d "$SITE"
echo "docs.sh: manual in $SITE/index.html"
