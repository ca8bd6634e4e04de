"""The package as a user meets it: its version, names, docstrings, and type stubs that
match the functions."""

import ast
import inspect
import re
from pathlib import Path

import wheelrail
import wheelrail._wheelrail as native

STUBS = Path(wheelrail.__file__).with_name("_wheelrail.pyi")


def test_the_version_is_the_librarys(root):
    # python/Cargo.toml's version is the package's (maturin); it follows the library's.
    library = re.search(r'^version = "(.+)"', (root / "Cargo.toml").read_text(), re.M)
    assert wheelrail.__version__ == library.group(1)


def test_input_error_is_a_value_error():
    assert issubclass(wheelrail.InputError, ValueError)


def test_every_function_has_numpydoc_sections():
    for name in ["run", "read_profile", "rigid_sweep", "equivalent_conicity", "hertz_ellipse", "fleet"]:
        doc = getattr(wheelrail, name).__doc__
        for section in ["Parameters", "Returns", "Raises"]:
            assert f"\n{section}\n---" in doc, f"{name}: {section}"


def stub_functions():
    """The functions of the stubs: name -> list of (name, kind, default) per overload."""
    tree = ast.parse(STUBS.read_text())
    found = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            a = node.args
            params = [(p.arg, "positional") for p in a.args] + [(p.arg, "keyword") for p in a.kwonlyargs]
            defaults = [None] * (len(a.args) - len(a.defaults)) + list(a.defaults) + list(a.kw_defaults)
            values = [ast.literal_eval(d) if d is not None else inspect.Parameter.empty for d in defaults]
            found.setdefault(node.name, []).append(
                [(n, k, v) for (n, k), v in zip(params, values)]
            )
    return found


def test_the_stubs_are_the_modules_signatures():
    stubs = stub_functions()
    public = {n for n in wheelrail.__all__ if inspect.isbuiltin(getattr(wheelrail, n))}
    assert set(stubs) == public
    for name, overloads in stubs.items():
        signature = inspect.signature(getattr(native, name))
        actual = [
            (p.name, "keyword" if p.kind == p.KEYWORD_ONLY else "positional", p.default)
            for p in signature.parameters.values()
        ]
        for params in overloads:
            assert params == actual, name


def test_the_stubs_name_every_class_and_attribute():
    tree = ast.parse(STUBS.read_text())
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    assert set(classes) == {"InputError", "Run"}
    properties = {f.name for f in classes["Run"].body if isinstance(f, ast.FunctionDef)}
    assert properties == {n for n in dir(wheelrail.Run) if not n.startswith("_")}
