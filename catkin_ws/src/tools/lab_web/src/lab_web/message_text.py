"""A ROS message as the YAML-like text `rostopic echo` prints, shortened for a web page: long arrays show their
first items and their length, big byte arrays (images) only their length. No ROS import: it reads a genpy
message's `__slots__` and `_slot_types`, which every generated message class has."""
import math

MAX_ITEMS = 12
MAX_TEXT = 20000


def _scalar(value):
    if isinstance(value, float):
        if math.isfinite(value):
            return repr(value)
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, str):
        return '"{}"'.format(value) if value == "" or value.strip() != value else value
    if isinstance(value, bytes):
        return "<{} bytes>".format(len(value))
    return str(value)


def _is_message(value):
    """A generated message (rospy's Time and Duration have slots too, but print inline as secs.nsecs)."""
    return hasattr(value, "_slot_types") and not hasattr(value, "nsecs")


def _lines(value, indent):
    pad = "  " * indent
    if _is_message(value):
        for name in value.__slots__:
            item = getattr(value, name)
            if _is_message(item) or (isinstance(item, (list, tuple)) and item and _is_message(item[0])):
                yield "{}{}:".format(pad, name)
                yield from _lines(item, indent + 1)
            else:
                yield "{}{}: {}".format(pad, name, _inline(item))
        return
    for item in value[:MAX_ITEMS]:   # a list of messages
        nested = list(_lines(item, indent + 1))
        yield "{}-".format(pad) + (" " + nested[0].strip() if nested else "")
        yield from nested[1:]
    if len(value) > MAX_ITEMS:
        yield "{}... ({} items)".format(pad, len(value))


def _inline(value):
    if isinstance(value, (list, tuple)):
        shown = ", ".join(_scalar(item) for item in value[:MAX_ITEMS])
        return "[{}{}]".format(shown, ", ... ({} items)".format(len(value)) if len(value) > MAX_ITEMS else "")
    if hasattr(value, "secs") and hasattr(value, "nsecs"):   # rospy Time and Duration
        return "{}.{:09d}".format(value.secs, value.nsecs)
    return _scalar(value)


def message_text(message):
    """The message's fields, one per line, nested messages indented by two spaces."""
    text = "\n".join(_lines(message, 0))
    return text if len(text) <= MAX_TEXT else text[:MAX_TEXT] + "\n... (cut at {} characters)".format(MAX_TEXT)
