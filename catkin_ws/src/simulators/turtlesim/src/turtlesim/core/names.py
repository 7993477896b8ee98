"""ROS graph resource name rules, as roscpp's names::validate applies them to a turtle name.

A turtle name becomes a NodeHandle namespace, so an invalid name makes roscpp throw
InvalidNameException with the texts reproduced here. The empty name is valid (it means
"auto-name" to spawn). Only ASCII letters and digits count as alphanumeric (C locale).
"""
import string

from turtlesim.core.errors import InvalidNameError

FIRST_CHARS = frozenset(string.ascii_letters + '/~')
OTHER_CHARS = frozenset(string.ascii_letters + string.digits + '/_')


def validate_name(name):
    """Raise InvalidNameError with roscpp's text if `name` is not a valid graph resource name.

    First character: a-z, A-Z, '/' or '~'. Following characters: a-z, A-Z, 0-9, '/' or '_'.
    The reported element index counts characters (roscpp counts bytes; same for ASCII).
    """
    if not name:
        return
    if name[0] not in FIRST_CHARS:
        raise InvalidNameError(
            'Character [%s] is not valid as the first character in Graph Resource Name [%s].  '
            'Valid characters are a-z, A-Z, / and in some cases ~.' % (name[0], name))
    for index, char in enumerate(name[1:], start=1):
        if char not in OTHER_CHARS:
            raise InvalidNameError(
                'Character [%s] at element [%d] is not valid in Graph Resource Name [%s].  '
                'Valid characters are a-z, A-Z, 0-9, / and _.' % (char, index, name))
