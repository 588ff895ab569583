"""The type stubs (lancer/__init__.pyi, lancer/_lancer.pyi, with py.typed) say what the package is:
every public name in a stub exists at run time and every public name at run time is in its stub,
class by class; the parameters of each function (names, order, kind, defaults of the Python-level
ones) are the run time's, read with inspect for Python functions and from pybind11's signature line
for compiled ones."""

import ast
import inspect
import pathlib
import re

import pytest

import lancer
from lancer import _lancer

PACKAGE = pathlib.Path(lancer.__file__).parent


def stub(name):
    return ast.parse((PACKAGE / name).read_text())


def public(names):
    return {n for n in names if not n.startswith("_") or n == "__version__"}


def stub_names(tree):
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.ImportFrom) and node.module == "_lancer":
            names.update(alias.asname for alias in node.names if alias.asname)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return public(names)


def stub_defs(tree):
    """{name: FunctionDef} of the module's functions and {class: {member: [FunctionDef, ...]}}."""
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {n.name: {} for n in tree.body if isinstance(n, ast.ClassDef)}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            for member in node.body:
                if isinstance(member, ast.FunctionDef):
                    classes[node.name].setdefault(member.name, []).append(member)
                elif isinstance(member, ast.AnnAssign):
                    classes[node.name][member.target.id] = []
    return functions, classes


def stub_parameters(function):
    """[(name, kind)] of a stub's function, self left out; kinds as inspect's."""
    arguments = function.args
    parameters = [(a.arg, "POSITIONAL_OR_KEYWORD") for a in arguments.posonlyargs + arguments.args]
    if arguments.vararg:
        parameters.append((arguments.vararg.arg, "VAR_POSITIONAL"))
    parameters += [(a.arg, "KEYWORD_ONLY") for a in arguments.kwonlyargs]
    if arguments.kwarg:
        parameters.append((arguments.kwarg.arg, "VAR_KEYWORD"))
    return [p for p in parameters if p[0] not in ("self", "cls")]


def stub_defaults(function):
    arguments = function.args
    positional = arguments.posonlyargs + arguments.args
    defaults = dict(zip([a.arg for a in positional[len(positional) - len(arguments.defaults):]], arguments.defaults))
    defaults.update({a.arg: d for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults) if d is not None})
    return {name: ast.literal_eval(value) for name, value in defaults.items()}


def runtime_parameters(function):
    """[(name, kind)] from inspect for a Python function, else from pybind11's signature line
    "name(self: T, a: int, *, b: str = 'x', **kwargs) -> R" (self left out)."""
    try:
        signature = inspect.signature(function)
        return [(p.name, p.kind.name) for p in signature.parameters.values() if p.name not in ("self", "cls")], signature
    except (ValueError, TypeError):
        pass
    line = (function.__doc__ or "").splitlines()[0]
    match = re.match(r"^\w+\((.*)\) -> ", line)
    assert match, f"no signature line in {function!r}: {line!r}"
    parameters, depth, part, parts = [], 0, "", []
    for character in match.group(1):  # split on the commas outside brackets
        depth += character in "([{"
        depth -= character in ")]}"
        if character == "," and depth == 0:
            parts.append(part.strip())
            part = ""
        else:
            part += character
    if part.strip():
        parts.append(part.strip())
    kind = "POSITIONAL_OR_KEYWORD"
    for text in parts:
        if text == "*":
            kind = "KEYWORD_ONLY"
        elif text.startswith("**"):
            parameters.append((text[2:], "VAR_KEYWORD"))
        else:
            parameters.append((text.split(":")[0].strip(), kind))
    return [p for p in parameters if p[0] != "self"], None


def check_function(runtime, definition, where):
    names, signature = runtime_parameters(runtime)
    expected = stub_parameters(definition)
    # pybind11 names **kwargs "kwargs": the stub may call them anything.
    normalise = lambda ps: [("**", k) if k == "VAR_KEYWORD" else (n, k) for n, k in ps]
    assert normalise(names) == normalise(expected), where
    if signature is not None:
        runtime_defaults = {p.name: p.default for p in signature.parameters.values() if p.default is not p.empty}
        assert runtime_defaults == stub_defaults(definition), where


def test_stubs_and_marker_are_in_the_package():
    assert (PACKAGE / "py.typed").exists()
    for name in ("__init__.pyi", "_lancer.pyi"):
        stub(name)  # valid Python


def test_package_names():
    tree = stub("__init__.pyi")
    assert stub_names(tree) == public(lancer.__all__) == public(
        n for n in dir(lancer) if not inspect.ismodule(getattr(lancer, n)))
    declared = next(n for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "__all__")
    assert ast.literal_eval(declared.value) == lancer.__all__


def test_compiled_module_names_and_members():
    tree = stub("_lancer.pyi")
    assert stub_names(tree) == public(dir(_lancer))
    functions, classes = stub_defs(tree)
    for name, members in classes.items():
        cls = getattr(_lancer, name)
        if issubclass(cls, BaseException):
            continue  # InputError's attributes are set on each instance
        # A class made only by the module (Volume) has pybind11's __init__ that refuses: not in the stub.
        constructor = "__init__" in vars(cls) and not isinstance(vars(cls)["__init__"], type(object.__init__))
        runtime = public(vars(cls)) | ({"__init__"} if constructor else set())
        assert public(members) | ({"__init__"} & set(members)) == runtime, name


@pytest.mark.parametrize("module, stub_file", [(_lancer, "_lancer.pyi"), (lancer, "__init__.pyi")])
def test_parameters(module, stub_file):
    functions, classes = stub_defs(stub(stub_file))
    for name, definition in functions.items():
        check_function(getattr(module, name), definition, f"{stub_file}: {name}")
    for class_name, members in classes.items():
        cls = getattr(module, class_name)
        for member, definitions in members.items():
            if not definitions or any(isinstance(d, ast.Name) and d.id == "property"
                                      for f in definitions for d in f.decorator_list):
                continue
            if any(isinstance(d, ast.Attribute) for f in definitions for d in f.decorator_list):
                continue  # a property's setter
            check_function(getattr(cls, member), definitions[0], f"{stub_file}: {class_name}.{member}")
