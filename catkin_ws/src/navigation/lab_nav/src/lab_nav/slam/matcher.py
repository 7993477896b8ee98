"""Scan-to-map matching: an exact correlative search (branch and bound over a two-level grid), then a
Gauss-Newton refinement below the cell size.

The map is turned into a likelihood field, exp(-d^2 / 2 sigma^2) of the distance d to the nearest occupied cell,
built on a window around the guess. A pose's score is the sum of the field at the scan's hit points, so a perfect
match of N beams scores N (gmapping's score is a sum over beams too, so its minimumScore reads the same way).

The search covers +-SEARCH_LINEAR_M and +-SEARCH_ANGULAR_RAD around the guess (odometry composed with the last
correction). Translations are whole cells; each rotation step moves the farthest point by at most one cell. A
coarse level holds, per cell, the maximum of the field over the BLOCK_CELLS x BLOCK_CELLS cells above and to the
right, so a block's coarse score bounds all of its cells' scores: blocks are expanded best first, and the search
stops when no unexpanded block can beat the best cell found (Olson 2009, "Real-time correlative scan matching").
The coarse scores, read as log-likelihoods, also give the pose distribution's entropy, which the node publishes
as ~entropy. Gauss-Newton steps on the bilinearly interpolated field then refine the best cell.
"""

import math
from dataclasses import dataclass

import numpy as np
from scipy.ndimage import distance_transform_edt

SEARCH_LINEAR_M = 0.4
SEARCH_ANGULAR_RAD = 0.25
BLOCK_CELLS = 4
# The search scores at most this many of the points (evenly spread over the scan); the refinement and the final
# score use them all. Half of a 360-beam scan finds the same cell at half the cost.
MAX_SEARCH_POINTS = 180


@dataclass(frozen=True)
class Match:
    """The best pose (x, y, theta) of the points' frame in the map, its score and the search's entropy."""

    pose: tuple
    score: float
    entropy: float


class ScanMatcher:
    """`sigma` (m) is the likelihood field's width; `iterations` the Gauss-Newton steps."""

    def __init__(self, sigma, iterations):
        self.sigma = sigma
        self.iterations = iterations

    def match(self, occupied, geometry, points, guess):
        """Best pose for `points` (N x 2, m, in the frame whose map pose is sought) against the boolean grid
        `occupied` [row, col] laid out by `geometry`, searched around `guess` (x, y, theta)."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        reach = float(np.hypot(*points.T).max()) if len(points) else 0.0
        field = _LocalField(occupied, geometry, guess, reach, self.sigma)
        if not len(points) or not field.any_obstacle:
            return Match(tuple(guess), 0.0, 0.0)
        angles = _search_angles(geometry.resolution, reach)
        rows, cols = field.cells(points[::-(-len(points) // MAX_SEARCH_POINTS)], guess, angles)
        block_scores, offsets = field.block_scores(rows, cols)
        best_score, best = -1.0, None
        order = np.argsort(block_scores, axis=None)[::-1]
        for flat in order:
            if block_scores.flat[flat] <= best_score:
                break
            angle, block_row, block_col = np.unravel_index(flat, block_scores.shape)
            score, d_row, d_col = field.best_in_block(rows[angle], cols[angle], offsets[block_row],
                                                      offsets[block_col])
            if score > best_score:
                best_score, best = score, (angle, d_row, d_col)
        angle, d_row, d_col = best
        pose = (guess[0] + d_col * geometry.resolution, guess[1] + d_row * geometry.resolution,
                guess[2] + angles[angle])
        pose, score = field.refine(points, pose, self.iterations)
        return Match(pose, max(score, best_score), _entropy(block_scores))


class _LocalField:
    """The likelihood field on a window of the grid around the guess, padded for the search's offsets."""

    def __init__(self, occupied, geometry, guess, reach, sigma):
        self.geometry = geometry
        res = geometry.resolution
        half = int(math.ceil((reach + SEARCH_LINEAR_M) / res)) + 2 * BLOCK_CELLS
        col, row = (int(v) for v in geometry.world_to_cell(guess[0], guess[1]))
        self.row0, self.col0 = row - half, col - half
        window = np.zeros((2 * half + 1, 2 * half + 1), dtype=bool)
        r_lo, r_hi = max(self.row0, 0), min(self.row0 + window.shape[0], occupied.shape[0])
        c_lo, c_hi = max(self.col0, 0), min(self.col0 + window.shape[1], occupied.shape[1])
        if r_lo < r_hi and c_lo < c_hi:
            window[r_lo - self.row0:r_hi - self.row0, c_lo - self.col0:c_hi - self.col0] = \
                occupied[r_lo:r_hi, c_lo:c_hi]
        self.any_obstacle = bool(window.any())
        distance = distance_transform_edt(~window) * res if self.any_obstacle else None
        self.field = np.exp(-0.5 * (distance / sigma) ** 2) if self.any_obstacle else window.astype(float)
        self.coarse = _block_maximum(_block_maximum(self.field, axis=0), axis=1)
        self.reach_cells = int(round(SEARCH_LINEAR_M / res / BLOCK_CELLS)) * BLOCK_CELLS

    def cells(self, points, guess, angles):
        """Window (row, col) indices (len(angles) x N) of the points rotated by guess + each angle."""
        theta = guess[2] + angles[:, None]
        xs = guess[0] + np.cos(theta) * points[:, 0] - np.sin(theta) * points[:, 1]
        ys = guess[1] + np.sin(theta) * points[:, 0] + np.cos(theta) * points[:, 1]
        cols, rows = self.geometry.world_to_cell(xs, ys)
        return rows - self.row0, cols - self.col0

    def block_scores(self, rows, cols):
        """Coarse scores [angle, block row, block col] and the blocks' first offsets (cells). The window is
        large enough for every point at every offset, so no index is out of range."""
        offsets = np.arange(-self.reach_cells, self.reach_cells, BLOCK_CELLS)
        width = self.coarse.shape[1]
        flat = (rows * width + cols)[:, None, None, :] + (offsets[:, None] * width + offsets[None, :])[..., None]
        return self.coarse.ravel()[flat].sum(axis=3), offsets

    def best_in_block(self, rows, cols, row_offset, col_offset):
        """(score, row offset, col offset) of the best cell of one block at one angle."""
        steps = np.arange(BLOCK_CELLS)
        width = self.field.shape[1]
        start = (rows + row_offset) * width + cols + col_offset
        flat = start[None, None, :] + (steps[:, None] * width + steps[None, :])[..., None]
        scores = self.field.ravel()[flat].sum(axis=2)
        i, j = np.unravel_index(np.argmax(scores), scores.shape)
        return float(scores[i, j]), row_offset + i, col_offset + j

    def refine(self, points, pose, iterations):
        """Gauss-Newton on sum(1 - field)^2 from `pose`; returns the best pose met and its score."""
        best_pose, best_score = tuple(pose), -1.0
        x = np.array(pose, dtype=float)
        for step in range(iterations + 1):
            values, grad_x, grad_y = self._interpolated(points, x)
            score = float(values.sum())
            if score > best_score:
                best_pose, best_score = tuple(float(v) for v in x), score
            if step == iterations:
                break
            c, s = math.cos(x[2]), math.sin(x[2])
            d_theta = (-s * points[:, 0] - c * points[:, 1]) * grad_x + (c * points[:, 0] - s * points[:, 1]) * grad_y
            jacobian = np.column_stack((grad_x, grad_y, d_theta))
            hessian = jacobian.T @ jacobian + 1e-9 * np.eye(3)
            x = x + np.linalg.solve(hessian, jacobian.T @ (1.0 - values))
        return best_pose, best_score

    def _interpolated(self, points, pose):
        """Bilinear field values at the points placed at `pose`, and the field's x/y gradient (per m) there."""
        res = self.geometry.resolution
        c, s = math.cos(pose[2]), math.sin(pose[2])
        xs = pose[0] + c * points[:, 0] - s * points[:, 1]
        ys = pose[1] + s * points[:, 0] + c * points[:, 1]
        fx = (xs - self.geometry.origin_x) / res - 0.5 - self.col0
        fy = (ys - self.geometry.origin_y) / res - 0.5 - self.row0
        c0, r0 = np.floor(fx).astype(int), np.floor(fy).astype(int)
        tx, ty = fx - c0, fy - r0
        width = self.field.shape[1]
        flat = self.field.ravel()
        index = r0 * width + c0
        f00, f01 = flat.take(index, mode="clip"), flat.take(index + 1, mode="clip")
        f10, f11 = flat.take(index + width, mode="clip"), flat.take(index + width + 1, mode="clip")
        values = (f00 * (1 - tx) + f01 * tx) * (1 - ty) + (f10 * (1 - tx) + f11 * tx) * ty
        grad_x = ((f01 - f00) * (1 - ty) + (f11 - f10) * ty) / res
        grad_y = ((f10 - f00) * (1 - tx) + (f11 - f01) * tx) / res
        return values, grad_x, grad_y


def _block_maximum(values, axis):
    """m[i] = max(values[i : i + BLOCK_CELLS]) along `axis`, zeros past the end."""
    padded = np.pad(values, [(0, BLOCK_CELLS - 1) if a == axis else (0, 0) for a in range(values.ndim)])
    length = values.shape[axis]
    result = values.copy()
    for shift in range(1, BLOCK_CELLS):
        np.maximum(result, padded.take(np.arange(shift, shift + length), axis=axis), out=result)
    return result


def _search_angles(resolution, reach):
    """Rotations tried around the guess: a step that moves a point at `reach` by at most one cell."""
    step = min(resolution / max(reach, resolution), SEARCH_ANGULAR_RAD)
    count = int(math.ceil(SEARCH_ANGULAR_RAD / step))
    return np.arange(-count, count + 1) * step


def _entropy(scores):
    """Shannon entropy (nats) of the pose distribution p ~ exp(score) over the coarse search cells."""
    weights = np.exp(scores - scores.max())
    p = weights / weights.sum()
    return float(-(p * np.log(np.maximum(p, 1e-300))).sum())
