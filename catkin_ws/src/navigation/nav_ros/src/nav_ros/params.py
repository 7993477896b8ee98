"""Private parameters read into typed values, with an error naming the parameter when a value is unusable."""
import rospy


class ParamError(ValueError):
    """A private parameter whose value has the wrong type or range."""


def read(name, default, kind=float):
    """~name as `kind` (float, int, bool or str), `default` when unset."""
    full = rospy.resolve_name("~" + name)
    value = rospy.get_param(full, default)
    if value is None:
        return None
    try:
        if kind is bool:
            if not isinstance(value, bool):
                raise TypeError
            return value
        if kind in (float, int) and isinstance(value, bool):
            raise TypeError
        return kind(value)
    except (TypeError, ValueError):
        raise ParamError(f"parameter {full} must be a {kind.__name__}, got {value!r}") from None

