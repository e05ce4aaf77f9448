"""The type stubs (python/hullkit/*.pyi, PEP 561): shipped with the installed package, equal to
the runtime by mypy's stubtest (which also checks the stubs themselves under --strict's flags),
good for a typed user of the API under mypy --strict (typed_consumer.py, also run to check its
annotations against the runtime's types), and strict enough to reject wrong uses
(typed_misuse.py: an error on each line marked "# error: why").
hullkit._core's signatures, which stubtest cannot read from pybind11, are compared with the ones
pybind11 writes in its docstrings.

mypy is Debian's python3-mypy (scripts/setup.sh installs it); the tests fail without it."""
import ast
import importlib.metadata
import importlib.util
import inspect
import os
import re
import subprocess
import sys

import pytest

import hullkit
import hullkit._core

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(os.path.abspath(hullkit.__file__))


@pytest.fixture(scope="module")
def mypy(tmp_path_factory):
    """Runs `python -m <module> args` with this interpreter (which finds the installed hullkit
    and its stubs) from an empty folder: (exit code, output). mypy runs with --strict and a
    cache shared by this module's runs."""
    if importlib.util.find_spec("mypy") is None:
        pytest.fail(f"mypy is not importable by {sys.executable}: install Debian's python3-mypy "
                    "(bash scripts/setup.sh installs it)", pytrace=False)
    folder = tmp_path_factory.mktemp("stubs")
    cache = str(folder / "mypy-cache")

    def run(module, *args):
        flags = ["--strict", "--cache-dir", cache, "--no-error-summary", "--show-error-codes"] if module == "mypy" else []
        done = subprocess.run([sys.executable, "-m", module, *flags, *args], cwd=folder, capture_output=True,
                              text=True, timeout=300)
        return done.returncode, done.stdout + done.stderr
    return run


def test_the_installed_package_ships_a_stub_per_module_and_py_typed():
    try:
        installed = {str(f) for f in importlib.metadata.files("hullkit") or ()}
    except importlib.metadata.PackageNotFoundError:
        pytest.fail("hullkit is not installed as a distribution (pip install ./python)", pytrace=False)
    modules = {f[:-3] for f in installed if re.fullmatch(r"hullkit/\w+\.py", f)} | {"hullkit/_core"}
    wanted = {f"{m}.pyi" for m in modules} | {"hullkit/py.typed"}
    assert wanted <= installed, f"not installed: {sorted(wanted - installed)} (package-data in python/pyproject.toml)"


# stubtest reads no --strict; these are its flags that concern stubs (the stubs' own mypy errors
# fail stubtest, so the stubs are checked under them in the same run).
STRICT_STUBS = """[mypy]
disallow_any_generics = True
disallow_subclassing_any = True
disallow_untyped_defs = True
disallow_incomplete_defs = True
implicit_reexport = False
strict_equality = True
warn_unused_ignores = True
"""


def test_stubtest_finds_the_stubs_equal_to_the_runtime(mypy, tmp_path):
    config = tmp_path / "mypy.ini"
    config.write_text(STRICT_STUBS)
    allowlist = os.path.join(HERE, "stubtest-allowlist.txt")
    code, output = mypy("mypy.stubtest", "--mypy-config-file", str(config), "--allowlist", allowlist, "hullkit")
    assert code == 0 and "Success: no issues found" in output, output


def test_a_typed_consumer_passes_mypy_strict_and_runs(mypy):
    consumer = os.path.join(HERE, "typed_consumer.py")
    code, output = mypy("mypy", consumer)
    assert code == 0 and output == "", output
    run = subprocess.run([sys.executable, consumer], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0 and "typed_consumer: ok" in run.stdout, run.stdout + run.stderr


def test_wrong_uses_are_rejected_line_by_line(mypy):
    misuse = os.path.join(HERE, "typed_misuse.py")
    with open(misuse) as file:
        marked = {n for n, line in enumerate(file, 1) if "  # error: " in line}
    code, output = mypy("mypy", misuse)
    errors = [int(m.group(1)) for m in re.finditer(r"^.*typed_misuse\.py:(\d+): error:", output, re.M)]
    assert code == 1 and sorted(errors) == sorted(marked), output


# ---- hullkit._core: the stub against pybind11's signatures ----------------------------------------

def _split(parameters):
    """'a: X[b, c] = {}, d: int' -> ['a: X[b, c] = {}', 'd: int'] (commas inside brackets kept)."""
    parts, depth, current = [], 0, ""
    for c in parameters:
        depth += (c in "[({") - (c in "])}")
        if c == "," and depth == 0:
            parts.append(current.strip())
            current = ""
        else:
            current += c
    return parts + ([current.strip()] if current.strip() else [])


def _pybind_type(text):
    """pybind11's name of a type as the stub spells it; None where only the kind is compared."""
    text = re.sub(r"numpy\.ndarray\[numpy\.(\w+)\]", r"NDArray[np.\1]", text.strip())
    return {"dict": None, "tuple": "tuple", "Dict[str, str]": None}.get(text, text)


def _pybind_signature(line):
    """(parameters [(name, type, has default)], return type) from pybind11's signature line (the
    docstring's first), without self."""
    found = re.fullmatch(r"\w+\((.*)\) -> (.+)", line)
    assert found, line
    parameters = []
    for part in _split(found.group(1)):
        name, _, rest = part.partition(":")
        kind, _, default = rest.partition(" = ")
        if not kind.strip().startswith("hullkit._core.") and name.strip() != "self":
            parameters.append((name.strip(), _pybind_type(kind), bool(default)))
    return parameters, _pybind_type(found.group(2))


def _stub_signature(function):
    """The same from the stub's ast.FunctionDef: names (None for positional-only), types."""
    a = function.args
    positional = [*a.posonlyargs, *a.args]
    defaults = [False] * (len(positional) - len(a.defaults)) + [True] * len(a.defaults)
    parameters = [(None if arg in a.posonlyargs else arg.arg, ast.unparse(arg.annotation), default)
                  for arg, default in zip(positional, defaults) if arg.arg != "self"]
    return parameters, ast.unparse(function.returns)


def _same_type(pybind, stub):
    if pybind is None:  # a dict: the stub names a TypedDict or a dict
        return re.fullmatch(r"_\w+|dict\[.*\]( \| dict\[.*\])*", stub) is not None
    return stub.startswith(f"{pybind}[") if pybind in ("tuple", "list") else pybind == stub


def _core_pairs():
    """(qualified name, pybind11's signature line, stub FunctionDef or None) for each function,
    method and property of hullkit._core; a property's line is "(arg0: Class) -> type"."""
    with open(os.path.join(PACKAGE, "_core.pyi")) as file:
        tree = ast.parse(file.read())
    stubs = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            stubs[node.name] = node
        elif isinstance(node, ast.ClassDef):
            stubs.update({f"{node.name}.{f.name}": f for f in node.body if isinstance(f, ast.FunctionDef)})
    for name, obj in vars(hullkit._core).items():
        members = vars(obj).items() if inspect.isclass(obj) and obj.__module__ == "hullkit._core" else ()
        if callable(obj) and not inspect.isclass(obj):
            yield name, obj.__doc__.strip().splitlines()[0], stubs.get(name)
        for member, value in members:
            doc = value.fget.__doc__ if isinstance(value, property) else getattr(value, "__doc__", None)
            if (member == "__init__" or not member.startswith("_")) and doc:
                yield f"{name}.{member}", doc.strip().splitlines()[0], stubs.get(f"{name}.{member}")


def test_the_core_stub_has_pybind11s_signatures():
    checked = 0
    for name, line, stub in _core_pairs():
        assert stub is not None, f"hullkit._core.{name} is not in _core.pyi"
        where = f"hullkit._core.{name}: pybind11 has {line!r}"
        stub_parameters, stub_returns = _stub_signature(stub)
        if line.startswith("("):  # a property: only its type
            assert _same_type(_pybind_type(line.partition(" -> ")[2]), stub_returns), where
            checked += 1
            continue
        parameters, returns = _pybind_signature(line)
        assert len(parameters) == len(stub_parameters), where
        for (pname, ptype, pdefault), (sname, stype, sdefault) in zip(parameters, stub_parameters):
            # pybind11 names unnamed arguments arg0, arg1...: positional-only in the stub.
            assert sname == (None if re.fullmatch(r"arg\d+", pname) else pname), where
            assert pdefault == sdefault and _same_type(ptype, stype), where
        assert _same_type(returns, stub_returns), where
        checked += 1
    assert checked > 30
