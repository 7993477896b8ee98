"""The floor as the camera sees it: the floor's primitives rasterised once into a lit texture, then sampled per
pixel by the camera (core.camera) wherever its ray meets the floor.

Rasterising: the scene primitives of the floor (core.scene_primitives, the same ones the top-down views draw) are
painted by the caller's rasteriser (view.floor_raster: Qt, antialiased by exact coverage, the painter of the
top-down views). A texel is TEXEL_M, coarser for floors whose longer side would exceed MAX_TEXTURE_SIDE_PX.
Colours are multiplied by materials.FLOOR_LIGHT, the floor as Gazebo lights it. Mip levels (each half the last,
Gaussian-filtered by pyrDown) serve distant rows, so the far floor does not alias.

Sampling: for a level pinhole camera the floor plane maps to the image by a homography, so cv2.warpPerspective
samples the texture bilinearly for a whole band of rows at once. Outside the floor rectangle the texture's border
colour, Gazebo's background grey (materials.SKY_RGB), shows.
"""

import math
from typing import NamedTuple, Optional

import numpy as np

from tb3_sim.core.materials import FLOOR_LIGHT, SKY_RGB
from tb3_sim.core.scene_primitives import primitives_of

TEXEL_M = 0.003
MAX_TEXTURE_SIDE_PX = 3072
MIP_LEVELS = 5


class FloorTexture:
    """The lit floor of a floor.Floor: `levels` (mip level k: texel TEXEL_M * 2^k), its rectangle `bounds`
    (x_min, y_min, x_max, y_max) and `texel_m`. Build with `of(floor, rasterise)`."""

    def __init__(self, levels, bounds, texel_m):
        self.levels = levels
        self.bounds = bounds
        self.texel_m = texel_m
        self.border = tuple(int(c) for c in SKY_RGB)

    @classmethod
    def of(cls, floor, rasterise):
        """The texture of the floor.Floor `floor`, its primitives drawn by `rasterise(primitives, layout)` (which
        returns the (rows, columns, 3) uint8 RGB image of a TextureLayout; view.floor_raster.rasterise paints them
        with Qt)."""
        import cv2  # about 0.4 s: paid by worlds with a floor layer only

        layout = TextureLayout.of(floor)
        pixels = rasterise(primitives_of(floor), layout)
        levels = [cv2.convertScaleAbs(pixels, alpha=FLOOR_LIGHT)]
        while len(levels) < MIP_LEVELS and min(levels[-1].shape[:2]) > 1:
            levels.append(cv2.pyrDown(levels[-1]))
        return cls(levels, layout.bounds, layout.texel_m)


class TextureLayout(NamedTuple):
    """Where the texture lies: `columns` x `rows` texels of `texel_m` metres, the corner of texel (0, 0) at world
    (left, top) = (bounds[0], bounds[3]); rows run towards -y."""

    columns: int
    rows: int
    texel_m: float
    bounds: tuple

    @classmethod
    def of(cls, floor):
        x0, y0, x1, y1 = floor.bounds()
        texel = max(TEXEL_M, max(x1 - x0, y1 - y0) / MAX_TEXTURE_SIDE_PX)
        columns, rows = math.ceil((x1 - x0) / texel - 1e-9), math.ceil((y1 - y0) / texel - 1e-9)
        return cls(columns, rows, texel, (x0, y1 - rows * texel, x0 + columns * texel, y1))


class FloorView(NamedTuple):
    """One frame's floor below the horizon: `rgb` (rows, W, 3) uint8 for image rows first_row.., and `inside`
    (rows, W) uint8, 255 where the ray meets the floor plane inside the floor rectangle (None unless asked for)."""

    rgb: np.ndarray
    inside: Optional[np.ndarray]


class FloorSampler:
    """Samples a FloorTexture for one level camera: `intrinsics` (core.camera.CameraIntrinsics), the optical
    centre `mount_height_m` above the floor, image rows from `first_row` down (the first row that sees floor).

    For a level pinhole camera the floor plane maps to the image by a homography, so each row band is one
    cv2.warpPerspective of a mip level (bilinear).
    Buffers are reused between frames, so an instance must not sample from two threads at once; the returned
    arrays are reused too."""

    def __init__(self, intrinsics, mount_height_m, first_row, texture):
        self.texture = texture
        self.intrinsics = intrinsics
        self.mount_height_m = mount_height_m
        self.first_row = first_row
        rows = np.arange(first_row, intrinsics.height, dtype=float)
        depth = mount_height_m * intrinsics.fy / (rows - intrinsics.cy)
        footprint = depth / intrinsics.fx
        with np.errstate(divide="ignore"):
            level = np.clip(np.floor(np.log2(footprint / texture.texel_m)), 0, len(texture.levels) - 1).astype(int)
        edges = np.concatenate(([0], np.flatnonzero(np.diff(level)) + 1, [len(rows)]))
        self._bands = [(int(level[a]), a, b) for a, b in zip(edges[:-1], edges[1:]) if b > a]
        self._rgb = np.empty((len(rows), intrinsics.width, 3), dtype=np.uint8)
        self._inside = np.empty((len(rows), intrinsics.width), dtype=np.uint8)
        self._ones = [np.full(pixels.shape[:2], 255, dtype=np.uint8) for pixels in texture.levels]

    def _homography(self, x, y, yaw, level, band_first):
        """3 x 3 map from texel (column, row) of mip `level` to image pixel (u, v - first_row - band_first)."""
        intr, texture = self.intrinsics, self.texture
        scale = texture.texel_m * 2 ** level
        x0, y1 = texture.bounds[0], texture.bounds[3]
        # Texel (c, r) of level k -> world (X, Y, 1); pyrDown keeps texel 2^k c of level 0 at texel c of level k.
        half = texture.texel_m / 2.0
        to_world = np.array(((scale, 0.0, x0 + half), (0.0, -scale, y1 - half), (0.0, 0.0, 1.0)))
        cos_yaw, sin_yaw = math.cos(yaw), math.sin(yaw)
        forward = np.array((cos_yaw, sin_yaw, -(cos_yaw * x + sin_yaw * y)))
        left = np.array((-sin_yaw, cos_yaw, sin_yaw * x - cos_yaw * y))
        row0 = self.first_row + band_first
        # Homogeneous (u w, v w, w) with w = forward depth: u = cx - fx left / d, v = cy + fy h / d.
        to_image = np.vstack((intr.cx * forward - intr.fx * left,
                              (intr.cy - row0) * forward + np.array((0.0, 0.0, intr.fy * self.mount_height_m)),
                              forward))
        return to_image @ to_world

    def sample(self, x, y, yaw, inside=False):
        """The FloorView from a camera at world (x, y) looking along `yaw` (rad)."""
        import cv2

        width = self.intrinsics.width
        for level, first, end in self._bands:
            homography = self._homography(x, y, yaw, level, first)
            cv2.warpPerspective(self.texture.levels[level], homography, (width, end - first), dst=self._rgb[first:end],
                                flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT,
                                borderValue=self.texture.border)
            if inside:
                cv2.warpPerspective(self._ones[level], homography, (width, end - first),
                                    dst=self._inside[first:end], flags=cv2.INTER_NEAREST,
                                    borderMode=cv2.BORDER_CONSTANT, borderValue=0)
        return FloorView(self._rgb, self._inside if inside else None)
