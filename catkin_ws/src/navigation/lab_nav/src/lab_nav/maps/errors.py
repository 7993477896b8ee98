"""The one error map files raise: the text is the line map_server prints before it exits (or answers change_map
with a failure)."""


class MapFileError(ValueError):
    """A map YAML or image that cannot be loaded; str() is the complete console message."""
