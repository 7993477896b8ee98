"""The page's service form: the fields of a service's request, and the page's values converted to them, with
the checks `rosservice call` makes (a value of the wrong kind, an integer out of its type's range). Only
requests made of plain fields (bool, numbers, string) can be called from the form, which covers the Week 4
services. No ROS import: it reads a generated request class's `__slots__` and `_slot_types`."""
import math

INTEGER_BITS = {"byte": (8, True), "char": (8, False), "int8": (8, True), "uint8": (8, False), "int16": (16, True),
                "uint16": (16, False), "int32": (32, True), "uint32": (32, False), "int64": (64, True),
                "uint64": (64, False)}
FLOATS = ("float32", "float64")
PLAIN_TYPES = ("bool", "string") + FLOATS + tuple(INTEGER_BITS)


class FormError(ValueError):
    """The service cannot be called from the form, or a value does not fit its field; the text says which."""


def request_fields(request_class):
    """[{"name", "type"}] of the request's fields; FormError if one is not a plain field."""
    fields = [{"name": name, "type": kind} for name, kind in zip(request_class.__slots__, request_class._slot_types)]
    for field in fields:
        if field["type"] not in PLAIN_TYPES:
            raise FormError("field {} is a {}: the form only calls services whose request fields are bool, numbers "
                            "or string (use rosservice call)".format(field["name"], field["type"]))
    return fields


def _integer(name, kind, value):
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise FormError("{} must be an integer".format(name))
    try:
        number = int(value) if not isinstance(value, float) or value.is_integer() else None
    except ValueError:
        number = None
    if number is None:
        raise FormError("{} must be an integer, got {!r}".format(name, value))
    bits, signed = INTEGER_BITS[kind]
    low, high = (-(2 ** (bits - 1)), 2 ** (bits - 1) - 1) if signed else (0, 2 ** bits - 1)
    if not low <= number <= high:
        raise FormError("{} must be a {} from {} to {}, got {}".format(name, kind, low, high, number))
    return number


def _float(name, value):
    if isinstance(value, bool):
        raise FormError("{} must be a number".format(name))
    try:
        number = float(value)
    except OverflowError:   # an integer too large for a float
        raise FormError("{} must be a number a float64 holds, got an integer of {} digits".format(
            name, len(str(abs(value))))) from None
    except (TypeError, ValueError):
        raise FormError("{} must be a number, got {!r}".format(name, value)) from None
    if not math.isfinite(number) and not isinstance(value, str):
        raise FormError("{} must be a number".format(name))
    return number


def _bool(name, value):
    if isinstance(value, bool):
        return value
    if isinstance(value, str) and value.lower() in ("true", "false"):
        return value.lower() == "true"
    raise FormError("{} must be true or false, got {!r}".format(name, value))


def request_values(request_class, values):
    """Keyword arguments for the request from the page's `values` (name -> value); fields the page left out
    keep the message's defaults. FormError names an unknown field or a value that does not fit."""
    fields = {field["name"]: field["type"] for field in request_fields(request_class)}
    unknown = sorted(set(values) - set(fields))
    if unknown:
        raise FormError("the request has no field {} (fields: {})".format(unknown[0], ", ".join(fields) or "none"))
    converted = {}
    for name, value in values.items():
        kind = fields[name]
        if kind == "bool":
            converted[name] = _bool(name, value)
        elif kind in FLOATS:
            converted[name] = _float(name, value)
        elif kind in INTEGER_BITS:
            converted[name] = _integer(name, kind, value)
        else:
            if not isinstance(value, str):
                raise FormError("{} must be a string".format(name))
            converted[name] = value
    return converted


def response_text(response):
    """The reply as `rosservice call` prints it: one `field: value` line per field."""
    return "\n".join("{}: {}".format(name, getattr(response, name)) for name in response.__slots__) or "(empty reply)"
