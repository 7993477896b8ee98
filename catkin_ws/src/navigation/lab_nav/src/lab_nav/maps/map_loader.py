"""A map YAML (or map_server's deprecated image + resolution form) loaded into a GridMap, as map_server does."""

from lab_nav.maps.geometry import MapGeometry
from lab_nav.maps.grid_map import GridMap
from lab_nav.maps.image_file import read_image
from lab_nav.maps.map_yaml import MapDescription, read_map_yaml
from lab_nav.maps.pixel_cells import pixels_to_cells

# map_server's deprecated `map_server IMAGE RESOLUTION` form: origin 0 and trinary mode; negate and the thresholds
# come from ~params with these defaults
DEPRECATED_DEFAULTS = {"negate": 0, "occupied_thresh": 0.65, "free_thresh": 0.196}


def load_image_map(description):
    """The GridMap a MapDescription's image gives; MapFileError when the image cannot be read."""
    pixels, has_alpha = read_image(description.image)
    cells = pixels_to_cells(pixels, has_alpha, description.mode, description.negate,
                            description.occupied_thresh, description.free_thresh)
    x, y, yaw = description.origin
    geometry = MapGeometry(resolution=description.resolution, width=cells.shape[1], height=cells.shape[0],
                           origin_x=x, origin_y=y, origin_yaw=yaw)
    return GridMap(geometry, cells)


def load_map(yaml_path):
    """(MapDescription, GridMap) of the map YAML `yaml_path`; MapFileError with map_server's message."""
    description = read_map_yaml(yaml_path)
    return description, load_image_map(description)


def deprecated_description(image_path, resolution, negate, occupied_thresh, free_thresh):
    """The MapDescription of `map_server IMAGE RESOLUTION`: the image path as given, origin 0, trinary."""
    return MapDescription(image=image_path, resolution=resolution, origin=(0.0, 0.0, 0.0), negate=negate,
                          occupied_thresh=occupied_thresh, free_thresh=free_thresh)
