"""The type checker's spelling of classes the package makes at run time
(tests/test_typing.py runs mypy; this holds the declarations to the run-time
classes, without mypy)."""
import ast
import inspect

import rollerrig._core as _core
from rollerrig.rig import contact


def _type_checking_class(module, name):
    """(field, annotation text) of class `name` declared under `if
    TYPE_CHECKING:` in `module`'s source."""
    tree = ast.parse(inspect.getsource(module))
    for node in ast.walk(tree):
        if (isinstance(node, ast.If) and isinstance(node.test, ast.Name)
                and node.test.id == "TYPE_CHECKING"):
            for item in node.body:
                if isinstance(item, ast.ClassDef) and item.name == name:
                    return [(s.target.id, ast.unparse(s.annotation)) for s in item.body
                            if isinstance(s, ast.AnnAssign)]
    raise AssertionError(f"{module.__name__}: no {name} under TYPE_CHECKING")


def test_wheel_contact_declared_as_the_c_fields():
    declared = _type_checking_class(contact, "WheelContact")
    expected = [(name, "_Vector" if width == 3 else "_Scalar")
                for name, width, *_ in _core.RIG_WHEEL_FIELDS]
    assert declared[:-1] == expected
    assert declared[-1][0] == "status"
    assert [n for n, _ in declared] == list(contact.WheelContact._fields)


def test_rig_contact_declared_as_the_run_time_class():
    # the type checker's RigContact is generic in its wheels' type (WheelContact
    # or NonHertzWheel by rig_contact's patch); its fields are the run-time class's
    declared = _type_checking_class(contact, "RigContact")
    assert [n for n, _ in declared] == list(contact.RigContact._fields)
    assert [a for n, a in declared if n in ("left", "right")] == ["_Wheel", "_Wheel"]
