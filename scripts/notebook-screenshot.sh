#!/usr/bin/env bash
# The example notebook as a reader sees it: executed headless (tools/docs/run_notebook.py,
# as the manual's build does), its HTML opened in Debian's headless Chromium and
# screenshotted. Usage: scripts/notebook-screenshot.sh [BUILD_DIR] [OUT.png]
# (default build/, build/notebook.png). Installs chromium when missing (~300 MB).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=$(cd "${1:-build}" && pwd)
OUT=${2:-$BUILD/notebook.png}
scripts/apt-install.sh chromium jupyter-nbconvert python3-ipykernel python3-ipywidgets
PYTHONPATH="$BUILD/python" /usr/bin/python3 tools/docs/run_notebook.py docs/notebooks/flowsurf.ipynb "$BUILD/notebook.html"
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1000,2400 \
  --virtual-time-budget=3000 --screenshot="$OUT" "file://$BUILD/notebook.html" 2>/dev/null
echo "notebook-screenshot: $OUT"
