"""params_demo.py's table: one name of each kind, with values the parameter server stores as they are."""
from beginner_tutorials.parameters import DEMO_PARAMETERS, MISSING_NAME


def test_every_kind_of_name_is_shown():
    kinds = {parameter.kind: parameter.name for parameter in DEMO_PARAMETERS}
    assert kinds["global"].startswith("/")
    assert kinds["private"].startswith("~")
    assert not kinds["relative"].startswith(("/", "~"))


def test_values_are_xmlrpc_scalars_and_names_are_unique():
    assert all(type(parameter.value) in (str, int, float, bool) for parameter in DEMO_PARAMETERS)
    names = [parameter.name for parameter in DEMO_PARAMETERS]
    assert len(set(names)) == len(names)
    assert MISSING_NAME not in names
