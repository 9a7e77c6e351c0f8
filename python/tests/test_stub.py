"""Python that an editor understands: the type stub names every public name and types every
option keyword of the option table; help(flowsurf.Renderer) lists the options."""
import ast
import os
import pydoc

import flowsurf

STUB = os.path.join(os.path.dirname(flowsurf.__file__), "__init__.pyi")


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def keywords_of(tree, cls, method):
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == cls:
            for f in node.body:
                if isinstance(f, ast.FunctionDef) and f.name == method:
                    return {a.arg: ast.unparse(a.annotation) for a in f.args.kwonlyargs}
    raise AssertionError("%s.%s missing from the stub" % (cls, method))


def test_stub_defines_every_public_name():
    tree = stub_tree()
    defined = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    assert set(flowsurf.__all__) <= defined, set(flowsurf.__all__) - defined
    assert os.path.exists(os.path.join(os.path.dirname(flowsurf.__file__), "py.typed"))


def test_stub_types_every_option_keyword():
    tree = stub_tree()
    for cls, method in (("Renderer", "__init__"), ("Renderer", "set"), ("Renderer", "frames")):
        kws = keywords_of(tree, cls, method)
        for o in flowsurf.option_info():
            name = o["name"].replace("-", "_")
            assert name in kws, (cls, method, name)
    kws = keywords_of(tree, "Renderer", "__init__")
    assert kws["method"] == "Literal['isa', 'ibfvs', 'hybrid'] | None"
    assert kws["alpha"] == "float | None" and kws["filter_length"] == "int | None"
    assert kws["size"].startswith("tuple[int, int]")


def test_help_lists_every_option_with_range_and_default():
    text = pydoc.render_doc(flowsurf.Renderer, renderer=pydoc.plaintext)
    for o in flowsurf.option_info():
        assert o["name"].replace("-", "_") + ":" in text, o["name"]
    assert "alpha: float 0..1 (default 0.08)" in text
    assert "method: isa|ibfvs|hybrid (default isa)" in text
