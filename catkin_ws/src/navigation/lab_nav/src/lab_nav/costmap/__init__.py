"""costmap_2d's layered costmap as numpy grids: cost values, footprint, static/obstacle/inflation layers."""
