"""The SLAM logic's one exception root."""


class SlamError(ValueError):
    """A bad parameter or input; the text names it and what is allowed."""
