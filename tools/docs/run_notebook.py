#!/usr/bin/env python3
"""Executes a notebook headless, as `jupyter nbconvert --to html --execute` does, and writes
its HTML; then checks what a reader of that page sees: no error output, and at least one
picture (image, video or animated PNG) per figure cell.

    run_notebook.py IN.ipynb OUT.html [--timeout S]

Debian 12 pairs nbclient 0.7 (which expects the widget messages of ipywidgets 7) with
ipywidgets 6, whose comm_open carries the state itself: `jupyter nbconvert --execute` then
fails with KeyError 'state' on the first widget. This runs the same NotebookClient with
that one handler tolerant of ipywidgets 6 (no widget state is stored either way), and with
FLOWSURF_JUPYTER_STILL=1, so that flowsurf.Player shows the frame it is on.
"""
import argparse
import os
import re
import sys

import nbformat
from nbclient import NotebookClient
from nbconvert import HTMLExporter


class Client(NotebookClient):
    def on_comm_open_jupyter_widget(self, msg):
        if "state" not in msg["content"]["data"]:   # ipywidgets 6: protocol 1
            return None
        return super().on_comm_open_jupyter_widget(msg)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("notebook")
    ap.add_argument("html")
    ap.add_argument("--timeout", type=int, default=600)
    args = ap.parse_args()
    nb = nbformat.read(args.notebook, as_version=4)
    os.environ["FLOWSURF_JUPYTER_STILL"] = "1"  # no page runs widgets here: the player as a still
    Client(nb, timeout=args.timeout, kernel_name="python3", store_widget_state=False,
           resources={"metadata": {"path": os.path.dirname(os.path.abspath(args.notebook))}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    if errors:
        sys.exit("run_notebook: %s: %s: %s" % (args.notebook, errors[0].ename, errors[0].evalue))
    html, _ = HTMLExporter().from_notebook_node(nb)
    os.makedirs(os.path.dirname(os.path.abspath(args.html)), exist_ok=True)
    with open(args.html, "w", encoding="utf-8") as f:
        f.write(html)
    pictures = len(re.findall(r'<img src="data:image/png;base64,|<video ', html))
    print("run_notebook: %s: %d code cells run, %d pictures, %s" % (
        args.notebook, sum(c.cell_type == "code" for c in nb.cells), pictures, args.html))
    if pictures == 0:
        sys.exit("run_notebook: no picture in the executed notebook")


if __name__ == "__main__":
    main()
