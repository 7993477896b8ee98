/*
 * view.js: the top-down canvas (#world) the world, robot and map panels draw on: its view transform (metres in
 * the fixed frame <-> canvas pixels, y up) and its layers, drawn in order of z on planes redrawn when they change.
 *
 * The fixed frame is "map" once a map has come, else "odom" (the map panel's `fixed` frames). What the robot
 * and world panels send is in odom (tb3_sim's world frame is odom's origin): their layers are drawn through
 * odom's pose in the fixed frame, applied as a canvas transform, so the robot goes map -> odom -> base_footprint
 * as in RViz and their drawing code knows nothing of it.
 */
import {$, addRenderer, app, isNumber, labView, requestRender, validRobot} from './core.js';

const VIEW_MARGIN_PX = 16;
export const ROBOT_RADIUS_M = 0.15;
export const COLORS = {
  floor: '#f4f4f0', grid: 'rgba(0, 0, 0, 0.07)', axis: 'rgba(0, 0, 0, 0.16)', static: '#555555',
  model: '#b07840', modelEdge: '#7d5226', otherRobot: 'rgba(20, 35, 110, 0.45)', robot: '#1f4ea3',
  heading: '#ffffff', trail: '#ff8c00', scan: '#e03030', selection: '#1f4ea3',
};

export const canvas = $('world');

/* The view is a stack of planes, each a canvas of its own (the compositor lays them over each other), each redrawn
   only when what it shows changed or the view moved. With one canvas redrawn whole for every state frame (25 a
   second), headless Chromium rasterised the map, both costmaps and amcl's 3000 arrows each time, on the page's main
   thread: it redrew about 4 times a second, and state frames waited behind it. Layers join a plane by their z.
   A plane with no odom-frame layer is not redrawn when odom moves in the fixed frame (amcl's corrections). */
const PLANES = [
  {name: 'grids', belowZ: 16},        // floor, 1 m grid, scene, map: a new map every 2 s while mapping
  {name: 'costmaps', belowZ: 18},     // move_base's two costmaps: up to 4 new pictures a second, the map not redrawn
  {name: 'particles', belowZ: 19},    // amcl's cloud in the fixed frame: thousands of arrows, when amcl updates
  {name: 'vectors', belowZ: 20},      // plans, amcl pose, goal, frontiers: nav frames, <= 5 a second
  {name: 'live', belowZ: Infinity},   // models, robots, trail, scan, robot, tools: every state frame
].map((plane) => Object.assign(plane, {layers: [], dirty: true, placement: null}));
const LIVE = PLANES[PLANES.length - 1];
// #world is the live plane: on top, it takes the mouse; the planes below it are drawn on canvases put under it.
// willReadFrequently: tests read pixels back with getImageData; without it Chromium warns in the console.
LIVE.context = canvas.getContext('2d', {willReadFrequently: true});
for (const plane of PLANES.slice(0, -1)) {
  const below = document.createElement('canvas');
  below.className = 'plane';
  below.width = canvas.width;
  below.height = canvas.height;
  canvas.before(below);
  plane.context = below.getContext('2d');
}
/** `draw(ctx)` paints one layer of the world view, lower z first (the grid is below 0), with coordinates in
 *  `frame`: 'odom' (the default) or 'fixed' (already in the fixed frame, as the map). Its panel calls
 *  redraw(planeOf(z)) when what it draws changes. */
export function addLayer(z, draw, frame = 'odom') {
  const plane = planeOf(z);
  plane.layers.push({z, draw, frame});
  plane.layers.sort((a, b) => a.z - b.z);
}

function planeOf(z) {
  return PLANES.find((plane) => z < plane.belowZ);
}

/** Redraws the plane named `name` ('grids', 'costmaps', 'particles', 'vectors' or 'live') at the next animation
 *  frame; every plane when no name is given (what decides which layer draws what changed, as the fixed frame). */
export function redraw(name) {
  for (const plane of PLANES) {
    if (name === undefined || plane.name === name) plane.dirty = true;
  }
  requestRender('world');
}

/** [x, y, yaw] of odom in the fixed frame (zeros while the fixed frame is odom). */
function odomPose() {
  const odom = app.fixed && app.fixed.odom;
  return Array.isArray(odom) && odom.length === 3 && odom.every(isNumber) ? odom : [0, 0, 0];
}

export function odomToFixed(x, y) {
  const [ox, oy, yaw] = odomPose();
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  return [ox + c * x - s * y, oy + s * x + c * y];
}

function fixedToOdom(x, y) {
  const [ox, oy, yaw] = odomPose();
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  return [c * (x - ox) + s * (y - oy), -s * (x - ox) + c * (y - oy)];
}

export function odomToPixel(x, y) {
  return worldToPixel(...odomToFixed(x, y));
}

export function pixelToOdom(px, py) {
  return fixedToOdom(...pixelToWorld(px, py));
}

/** The canvas transform that takes where a drawer puts an odom point (worldToPixel of it) to where it is. */
function odomCanvasTransform() {
  const [, , yaw] = odomPose();
  const [ax, ay] = worldToPixel(0, 0);
  const [bx, by] = odomToPixel(0, 0);
  const c = Math.cos(yaw);
  const s = Math.sin(yaw);
  // Pixels turn the other way (y down): q -> R' (q - a) + b with R' = [[c, s], [-s, c]].
  return [c, -s, s, c, bx - (c * ax + s * ay), by - (-s * ax + c * ay)];
}

function validBounds(world) {
  const b = world && world.bounds;
  if (!Array.isArray(b) || b.length !== 4 || !b.every(isNumber) || b[2] <= b[0] || b[3] <= b[1]) return null;
  return b;
}

function fitRegion(region, key) {
  const width = Math.max(region[2] - region[0], 0.1);
  const height = Math.max(region[3] - region[1], 0.1);
  const scale = Math.min((canvas.width - 2 * VIEW_MARGIN_PX) / width, (canvas.height - 2 * VIEW_MARGIN_PX) / height);
  return {key, region, scale, cx: (region[0] + region[2]) / 2, cy: (region[1] + region[3]) / 2};
}

export function currentView() {
  if (!app.view) app.view = fitRegion([-5, -5, 5, 5], null);
  return app.view;
}

/** The world's bounds (odom) in the fixed frame, taking in the map's. */
function fixedBounds() {
  const regions = [];
  const world = validBounds(app.world);
  if (world) {
    const corners = [[world[0], world[1]], [world[2], world[1]], [world[0], world[3]], [world[2], world[3]]]
      .map(([x, y]) => odomToFixed(x, y));
    regions.push([Math.min(...corners.map((p) => p[0])), Math.min(...corners.map((p) => p[1])),
      Math.max(...corners.map((p) => p[0])), Math.max(...corners.map((p) => p[1]))]);
  }
  const map = validBounds(app.mapRegion && {bounds: app.mapRegion});
  if (map) regions.push(map);
  if (!regions.length) return null;
  return [0, 1, 2, 3].map((i) => (i < 2 ? Math.min : Math.max)(...regions.map((r) => r[i])))
    .map((v) => Math.round(v * 1000) / 1000);
}

/** Refits only when the bounds change, or when the robot would be drawn outside the canvas. */
export function updateView() {
  const bounds = fixedBounds();
  const odomRobot = validRobot(app.state && app.state.robot);
  const robot = odomRobot && Object.assign({}, odomRobot, {x: odomToFixed(odomRobot.x, odomRobot.y)[0],
    y: odomToFixed(odomRobot.x, odomRobot.y)[1]});
  const key = bounds ? bounds.join(',') : 'none';
  if (!app.view || app.view.key !== key) {
    const pad = 3;
    const base = bounds || (robot ? [robot.x - pad, robot.y - pad, robot.x + pad, robot.y + pad] : [-5, -5, 5, 5]);
    app.view = fitRegion(base, key);
  }
  if (robot && !robotFullyVisible(robot)) {
    const r = app.view.region;
    const pad = 0.5;
    app.view = fitRegion([Math.min(r[0], robot.x - pad), Math.min(r[1], robot.y - pad),
      Math.max(r[2], robot.x + pad), Math.max(r[3], robot.y + pad)], key);
  }
}

function robotFullyVisible(robot) {
  const [px, py] = worldToPixel(robot.x, robot.y);
  const r = ROBOT_RADIUS_M * currentView().scale;
  return px - r >= 0 && py - r >= 0 && px + r <= canvas.width && py + r <= canvas.height;
}

export function worldToPixel(x, y) {
  const v = currentView();
  return [canvas.width / 2 + (x - v.cx) * v.scale, canvas.height / 2 - (y - v.cy) * v.scale];
}

export function pixelToWorld(px, py) {
  const v = currentView();
  return [v.cx + (px - canvas.width / 2) / v.scale, v.cy - (py - canvas.height / 2) / v.scale];
}

labView.worldToPixel = worldToPixel;
labView.pixelToWorld = pixelToWorld;
labView.odomToPixel = odomToPixel;

/** A canvas pixel of a mouse event. */
export function canvasPoint(event) {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

/** Redraws the planes that changed; all of them when the view, the fixed frame or odom's place in it moved. */
function drawWorld() {
  const fixed = app.fixed || {};
  const odom = odomCanvasTransform();
  for (const plane of PLANES) {
    const movesWithOdom = plane.layers.some((layer) => layer.frame === 'odom');
    const placement = JSON.stringify([currentView(), movesWithOdom ? fixed : [fixed.frame, fixed.odom_frame]]);
    if (placement !== plane.placement) {
      plane.placement = placement;
      plane.dirty = true;
    }
    if (!plane.dirty) continue;
    plane.dirty = false;
    const ctx = plane.context;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.globalAlpha = 1;
    if (plane === PLANES[0]) {
      ctx.fillStyle = COLORS.floor;
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      drawGrid(ctx);
    } else {
      ctx.clearRect(0, 0, canvas.width, canvas.height);
    }
    for (const layer of plane.layers) {
      ctx.save();
      if (layer.frame === 'odom') ctx.setTransform(...odom);
      layer.draw(ctx);
      ctx.restore();
    }
  }
}

/** A faint 1 m grid, with the x and y axes a little darker; skipped when lines would crowd. */
function drawGrid(ctx) {
  const scale = currentView().scale;
  if (scale < 6) return;
  const [x0, y1] = pixelToWorld(0, 0);
  const [x1, y0] = pixelToWorld(canvas.width, canvas.height);
  ctx.lineWidth = 1;
  for (let gx = Math.ceil(x0); gx <= x1; gx++) {
    const px = Math.round(worldToPixel(gx, 0)[0]) + 0.5;
    strokeLine(ctx, px, 0, px, canvas.height, gx === 0 ? COLORS.axis : COLORS.grid);
  }
  for (let gy = Math.ceil(y0); gy <= y1; gy++) {
    const py = Math.round(worldToPixel(0, gy)[1]) + 0.5;
    strokeLine(ctx, 0, py, canvas.width, py, gy === 0 ? COLORS.axis : COLORS.grid);
  }
}

export function strokeLine(context, ax, ay, bx, by, color) {
  context.strokeStyle = color;
  context.beginPath();
  context.moveTo(ax, ay);
  context.lineTo(bx, by);
  context.stroke();
}

export function tracePath(context, points) {
  context.beginPath();
  points.forEach((point, i) => {
    const [px, py] = worldToPixel(point[0], point[1]);
    if (i === 0) context.moveTo(px, py);
    else context.lineTo(px, py);
  });
}

/** A box or circle model at (x, y), keeping its own yaw. */
export function drawBody(context, body, x, y, fill, edge) {
  const [px, py] = worldToPixel(x, y);
  const s = currentView().scale;
  context.save();
  context.translate(px, py);
  context.rotate(-(body.yaw || 0));       // the canvas y axis points down, so angles turn the other way
  context.beginPath();
  if (body.kind === 'circle') context.arc(0, 0, Math.max(body.r * s, 2), 0, 2 * Math.PI);
  else context.rect(-body.sx * s / 2, -body.sy * s / 2, body.sx * s, body.sy * s);
  context.fillStyle = fill;
  context.fill();
  if (edge) {
    context.lineWidth = edge.width || 1;
    context.strokeStyle = edge.color;
    context.setLineDash(edge.dash || []);
    context.stroke();
  }
  context.restore();
}

addRenderer('world', drawWorld, () => !$('world-panel').hidden);

/** An occupancy grid's picture (a pixel per cell, row 0 first) where its origin [x, y, yaw] and resolution put it:
 *  flipped (row 0 at the lowest y), cells kept sharp as RViz draws them. */
export function drawGridImage(context, image, grid, alpha = 1) {
  const [x, y, yaw] = grid.origin;
  const [px, py] = worldToPixel(x, y);
  const scale = grid.resolution * currentView().scale;
  context.save();
  context.globalAlpha = alpha;
  context.translate(px, py);
  context.rotate(-(yaw || 0));
  context.scale(scale, -scale);
  context.imageSmoothingEnabled = false;
  context.drawImage(image, 0, 0);
  context.restore();
}
