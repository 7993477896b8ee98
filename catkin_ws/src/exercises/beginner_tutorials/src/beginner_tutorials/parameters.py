"""The parameters params_demo.py sets, reads back and deletes: one of each kind of name.

A global name ("/...") is used as is; a relative name resolves in the node's namespace (ROS_NAMESPACE or
__ns:=); a private name ("~...") resolves under the node's own name. Values are the types the parameter
server stores (str, int, float, bool).
"""
from typing import NamedTuple

MISSING_NAME = "/params_demo_never_set"
MISSING_DEFAULT = "not set"


class DemoParameter(NamedTuple):
    name: str
    value: object
    kind: str


DEMO_PARAMETERS = (
    DemoParameter("/robot_name", "waffle", "global"),
    DemoParameter("max_speed", 0.26, "relative"),
    DemoParameter("~publish_rate_hz", 10, "private"),
    DemoParameter("/use_lidar", True, "global"),
)
