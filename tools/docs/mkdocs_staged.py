"""MkDocs hook: `mkdocs build` from the repository root builds the manual that scripts/docs.sh
staged, since part of it is generated (the option reference, the API pages, the gallery's
images, the benchmark pages). docs.sh's own config names the staged folder itself, and this
hook then does nothing. Without a staged copy as new as docs/, the build stops and says what
to run instead of failing on each generated page."""
import os

from mkdocs.exceptions import PluginError


def _newest(folder):
    return max((os.path.getmtime(os.path.join(d, f)) for d, _, files in os.walk(folder) for f in files), default=0.0)


def on_config(config):
    root = os.path.dirname(os.path.abspath(config.config_file_path))
    docs = os.path.join(root, "docs")
    if os.path.abspath(config.docs_dir) != docs:
        return config  # scripts/docs.sh's staged config
    staged = os.path.join(root, "build", "docs-src")
    if not os.path.isdir(staged):
        raise PluginError("the manual has generated pages: build it with scripts/docs.sh (after scripts/build.sh), "
                          "which stages docs/ with them in build/docs-src and builds build/site; "
                          "mkdocs build then builds that staged copy")
    if _newest(docs) > _newest(staged):
        raise PluginError("build/docs-src is older than docs/: run scripts/docs.sh again to stage the manual")
    config.docs_dir = staged
    return config
