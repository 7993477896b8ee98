"""explore_lite's goal choice: the cheapest frontier whose centroid is not near a blacklisted goal.

A goal is blacklisted when move_base aborts it or it makes no progress for progress_timeout; a centroid counts as
on the blacklist when it lies within 5 cells of a blacklisted point in both x and y (strictly less than
5 * resolution in each axis, a square, as in the original).
"""

BLACKLIST_TOLERANCE_CELLS = 5


def on_blacklist(point, blacklist, resolution):
    """Whether `point` (x, y) lies within the tolerance square of any blacklisted (x, y)."""
    tolerance = BLACKLIST_TOLERANCE_CELLS * resolution
    return any(abs(point[0] - x) < tolerance and abs(point[1] - y) < tolerance for x, y in blacklist)


def next_frontier(frontiers, blacklist, resolution):
    """The first frontier (they come sorted by cost) whose centroid is not on the blacklist, or None."""
    return next((frontier for frontier in frontiers if not on_blacklist(frontier.centroid, blacklist, resolution)),
                None)
