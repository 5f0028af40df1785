"""python/linemap.pyi, the module's type stubs, against the built module:
the same public names, and for every function and method the same
parameters (names, order, keyword-only or not, defaults) as the signature
pybind11 reports on the first line of its docstring. Types are not compared
(the stubs narrow pybind11's `object`)."""
import ast
import pathlib

import pytest

linemap = pytest.importorskip("linemap")

STUBS = pathlib.Path(__file__).resolve().parents[2] / "python" / "linemap.pyi"


def stub_tree():
    return ast.parse(STUBS.read_text(), filename=str(STUBS))


def parameters(fn):
    """(name, keyword-only, default) of each parameter but self, in order;
    defaults as Python values (None when there is none, ... for a default
    that is not a literal)."""
    args = fn.args
    out = []
    plain = args.posonlyargs + args.args
    defaults = [None] * (len(plain) - len(args.defaults)) + list(args.defaults)
    for a, d in zip(plain, defaults):
        out.append((a.arg, False, literal(d)))
    for a, d in zip(args.kwonlyargs, args.kw_defaults):
        out.append((a.arg, True, literal(d)))
    return [p for p in out if p[0] != "self"]


def literal(node):
    if node is None:
        return None
    try:
        return ast.literal_eval(node)
    except ValueError:
        return ...


def runtime_parameters(obj):
    """The parameters of pybind11's signature line, parsed as a def."""
    line = obj.__doc__.strip().splitlines()[0]
    assert "(" in line and not line.startswith("Overloaded"), line
    name = line[: line.index("(")]
    tree = ast.parse("def " + name + line[len(name):] + ": ...")
    return parameters(tree.body[0])


def stub_functions(body):
    return {n.name: n for n in body if isinstance(n, ast.FunctionDef)}


def test_stubs_name_every_public_name_of_the_module():
    tree = stub_tree()
    named = set(stub_functions(tree.body))
    named |= {n.name for n in tree.body if isinstance(n, ast.ClassDef)}
    named |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    named = {n for n in named if not n.startswith("_") or n == "__version__"}
    public = {n for n in dir(linemap) if not n.startswith("_")} | {"__version__"}
    assert named == public


def test_functions_have_the_modules_parameters():
    functions = stub_functions(stub_tree().body)
    for name, fn in functions.items():
        assert parameters(fn) == runtime_parameters(getattr(linemap, name)), name


@pytest.mark.parametrize("class_name", ["Map", "DecodeLimits"])
def test_classes_have_the_modules_methods_and_properties(class_name):
    (cls,) = [n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == class_name]
    runtime_class = getattr(linemap, class_name)
    getters, setters, methods = set(), set(), {}
    for fn in [n for n in cls.body if isinstance(n, ast.FunctionDef)]:
        decorators = [ast.unparse(d) for d in fn.decorator_list]
        if "property" in decorators:
            getters.add(fn.name)
        elif any(d.endswith(".setter") for d in decorators):
            setters.add(fn.name)
        else:
            methods[fn.name] = fn
    runtime = vars(runtime_class)
    properties = {n for n, v in runtime.items() if isinstance(v, property)}
    assert getters == properties
    assert setters == {n for n in properties if runtime[n].fset is not None}
    public = {n for n, v in runtime.items()
              if not n.startswith("_") and not isinstance(v, property)} | {"__init__"}
    assert set(methods) == public
    for name, fn in methods.items():
        assert parameters(fn) == runtime_parameters(getattr(runtime_class, name)), name


def test_stubs_sit_beside_the_built_module():
    built = pathlib.Path(linemap.__file__).with_name("linemap.pyi")
    assert built.read_text() == STUBS.read_text()
