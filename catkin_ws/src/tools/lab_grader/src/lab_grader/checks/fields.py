"""Comparing message fields (a service reply, an action result) with what a suite expects, in words (plain
Python). A field's expected value is compared strictly about kinds, and a text field may be matched by regex."""

MAX_SHOWN_TEXT = 80


def shown(value):
    """A value for a one-line reason: strings quoted and cut at MAX_SHOWN_TEXT characters."""
    if isinstance(value, str):
        text = value if len(value) <= MAX_SHOWN_TEXT else value[:MAX_SHOWN_TEXT - 3] + "..."
        return repr(text)
    return repr(value)


def same_value(got, want):
    """Field equality, strict about kinds: True is not 1, 1 equals 1.0 (float32 fields: within 1e-6); integers
    compare exactly (an int64 sum off by one at 2**63 is wrong, however large)."""
    if isinstance(want, bool) or isinstance(got, bool):
        return isinstance(got, bool) and isinstance(want, bool) and got == want
    if isinstance(want, int) and isinstance(got, int):
        return got == want
    if isinstance(want, (int, float)):
        return isinstance(got, (int, float)) and abs(got - want) <= 1e-6 * max(1.0, abs(want))
    return got == want


def field_problems(equal, matches, got, what="reply"):
    """The problems, in words, of fields `got` (a dict) against `equal` {field: value} and `matches`
    {field: compiled regex}; `what` names the message ("reply", "result")."""
    problems = []
    for field, want in equal.items():
        if field not in got:
            problems.append("expected a {} field {}, the {} has none".format(what, field, what))
        elif not same_value(got[field], want):
            problems.append("expected {} {}, it {} {}".format(field, shown(want), "replied" if what == "reply"
                                                              else "gave", shown(got[field])))
    for field, pattern in matches.items():
        if field not in got:
            problems.append("expected a {} field {}, the {} has none".format(what, field, what))
        elif not pattern.search(str(got[field])):
            problems.append("expected {} to match /{}/, it {} {}".format(
                field, pattern.pattern, "replied" if what == "reply" else "gave", shown(got[field])))
    return problems
