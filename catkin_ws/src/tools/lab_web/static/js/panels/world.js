/*
 * The world panel: tb3_sim's world from above (`world`: walls, models, other robots; `scene`: the floor layer and
 * static shapes as tb3_sim's drawing primitives, sent once), and the box tool: click the floor to drop a box, drag
 * a box to move it, right-click or Delete to remove it, and the Reset world button.
 */
import {$, addVisibility, app, labView, isPageKey, request, updatePanels, validRobot}
  from '../core.js';
import {COLORS, ROBOT_RADIUS_M, addLayer, canvas, canvasPoint, currentView, drawBody, pixelToOdom, redraw,
  tracePath, updateView, worldToPixel} from '../view.js';

const CLICK_SLOP_PX = 4;              // mouse travel up to this is a click, beyond it a drag
const CAP_HEIGHT_PER_EM = 0.73;       // DejaVu Sans: a Text's height is its cap height
const sceneImages = new Map();        // data URL -> HTMLImageElement
const round3 = (value) => Math.round(value * 1000) / 1000;

function onWorld(frame) {
  app.world = frame;
  labView.models = Array.isArray(frame.models) ? frame.models : [];
  if (app.selectedModel && !findModel(app.selectedModel)) app.selectedModel = null;
  if (app.mouse && app.mouse.model && !findModel(app.mouse.model.name)) app.mouse = null;
  updateView();
  updatePanels();
  redraw('live');
}

function onScene(frame) {
  app.scene = Array.isArray(frame.primitives) ? frame.primitives : null;
  labView.scenePrimitives = app.scene ? app.scene.length : 0;
  labView.sceneFrames += 1;
  redraw('grids');
}

function hasWorld() {
  const w = app.world;
  return app.robotSeen || Boolean(w && ((w.static || []).length || (w.models || []).length || (w.robots || []).length));
}

function updateVisibility() {
  const section = $('world-panel');
  const shown = hasWorld();
  const wasHidden = section.hidden;
  section.hidden = !shown;
  $('reset-world').hidden = !shown;     // tb3_sim's /gazebo/reset_world: nothing to reset on turtlesim
  if (wasHidden && shown) redraw();
  return shown;
}

/* ============================================================ drawing */

/* Scene primitives (tb3_sim.core.primitives, sent as data): one drawer per kind, so the page draws every kind of
   floor marking without knowing any. Units are metres, colours [r, g, b]. */

/** A primitive's colour; none (a wall the world file gave no colour) is the page's wall colour. */
function rgbText(rgb) {
  return Array.isArray(rgb) ? `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})` : COLORS.static;
}

function sceneImage(src) {
  if (!sceneImages.has(src)) {
    const image = new Image();
    image.onload = () => redraw('grids');
    image.src = src;
    sceneImages.set(src, image);
  }
  return sceneImages.get(src);
}

/** Moves the context's origin to world point `at`, turned by `angleDeg` anticlockwise (y up in the world). */
function placeAt(ctx, at, angleDeg) {
  const [px, py] = worldToPixel(at[0], at[1]);
  ctx.translate(px, py);
  ctx.rotate(-angleDeg * Math.PI / 180);
}

const PRIMITIVE_DRAWERS = {
  FilledPolygon(ctx, p) {
    ctx.beginPath();
    for (const ring of p.rings) {
      ring.forEach((point, i) => {
        const [px, py] = worldToPixel(point[0], point[1]);
        if (i === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      });
      ctx.closePath();
    }
    ctx.fillStyle = rgbText(p.rgb);
    ctx.fill('evenodd');
  },
  Polyline(ctx, p) {
    tracePath(ctx, p.points);
    if (p.closed) ctx.closePath();
    ctx.strokeStyle = rgbText(p.rgb);
    ctx.lineWidth = Math.max(p.width * currentView().scale, 1);
    ctx.lineCap = 'butt';
    ctx.lineJoin = 'round';
    ctx.stroke();
  },
  Disc(ctx, p) {
    const [px, py] = worldToPixel(p.center[0], p.center[1]);
    ctx.beginPath();
    ctx.arc(px, py, Math.max(p.radius * currentView().scale, 1), 0, 2 * Math.PI);
    ctx.fillStyle = rgbText(p.rgb);
    ctx.fill();
  },
  Text(ctx, p) {
    placeAt(ctx, p.position, p.angle_deg);
    ctx.font = `${p.bold ? 'bold ' : ''}${p.height * currentView().scale / CAP_HEIGHT_PER_EM}px "DejaVu Sans", sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillStyle = rgbText(p.rgb);
    ctx.fillText(p.text, 0, 0);
  },
  Image(ctx, p) {
    const image = sceneImage(p.src);
    if (!image.complete || !image.naturalWidth) return;
    const scale = currentView().scale;
    placeAt(ctx, p.center, p.yaw_deg);
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(image, -p.size[0] * scale / 2, -p.size[1] * scale / 2, p.size[0] * scale, p.size[1] * scale);
  },
};

/** The floor layer and static shapes as tb3_sim's scene primitives; the markers' shapes where none came. */
function drawScene(ctx) {
  if (!Array.isArray(app.scene)) {
    for (const shape of (app.world || {}).static || []) drawShape(ctx, shape);
    return;
  }
  for (const primitive of app.scene) {
    const draw = PRIMITIVE_DRAWERS[primitive.kind];
    if (!draw) continue;
    ctx.save();
    draw(ctx, primitive);
    ctx.restore();
  }
}

function drawShape(ctx, shape) {
  ctx.fillStyle = COLORS.static;
  ctx.strokeStyle = COLORS.static;
  if (shape.kind === 'circle') {
    const [px, py] = worldToPixel(shape.x, shape.y);
    ctx.beginPath();
    ctx.arc(px, py, Math.max(shape.r * currentView().scale, 1), 0, 2 * Math.PI);
    ctx.fill();
  } else if (shape.kind === 'segment' && Array.isArray(shape.points)) {
    tracePath(ctx, shape.points);
    ctx.lineWidth = 3;
    ctx.lineCap = 'round';
    ctx.stroke();
  } else if (shape.kind === 'polygon' && Array.isArray(shape.points)) {
    tracePath(ctx, shape.points);
    ctx.closePath();
    ctx.fill();
  }
}

function drawModels(ctx) {
  for (const model of (app.world || {}).models || []) {
    const dragged = app.mouse && app.mouse.dragging && app.mouse.model === model;
    ctx.globalAlpha = dragged ? 0.3 : 1;     // its old place stays faintly visible while dragging
    const selected = model.name === app.selectedModel;
    drawBody(ctx, model, model.x, model.y, COLORS.model,
      selected ? {color: COLORS.selection, width: 2, dash: [4, 3]} : {color: COLORS.modelEdge});
    ctx.globalAlpha = 1;
  }
}

/** world.robots (2 Hz) includes the driven robot too, drawn from /odom by the robot panel: only the others. */
function drawOtherRobots(ctx) {
  const own = (app.state || {}).robot;
  const OWN_ROBOT_RADIUS_M = 0.35;
  for (const robot of (app.world || {}).robots || []) {
    if (own && Math.hypot(robot.x - own.x, robot.y - own.y) < OWN_ROBOT_RADIUS_M) continue;
    drawBody(ctx, robot, robot.x, robot.y, COLORS.otherRobot);
  }
}

function drawDraggedModel(ctx) {
  const m = app.mouse;
  if (!m || !m.dragging) return;
  const [x, y] = pixelToOdom(m.current[0], m.current[1]);
  drawBody(ctx, m.model, x, y, COLORS.model, {color: COLORS.selection, width: 2});
}

/* ============================================================ box tool */

function findModel(name) {
  return labView.models.find((model) => model.name === name) || null;
}

function hitsBody(body, x, y, tolerance) {
  const dx = x - body.x;
  const dy = y - body.y;
  if (body.kind === 'circle') return Math.hypot(dx, dy) <= body.r + tolerance;
  const c = Math.cos(-(body.yaw || 0));
  const s = Math.sin(-(body.yaw || 0));
  return Math.abs(dx * c - dy * s) <= body.sx / 2 + tolerance && Math.abs(dx * s + dy * c) <= body.sy / 2 + tolerance;
}

/** The topmost (last drawn) model under a canvas pixel, with 3 px of slack for small boxes. */
function modelAt(px, py) {
  const [x, y] = pixelToOdom(px, py);
  const tolerance = 3 / currentView().scale;
  const models = labView.models;
  for (let i = models.length - 1; i >= 0; i--) {
    if (hitsBody(models[i], x, y, tolerance)) return models[i];
  }
  return null;
}

function spawnBox(px, py) {
  const [x, y] = pixelToOdom(px, py);
  const robot = validRobot(app.state && app.state.robot);
  if (robot && Math.hypot(x - robot.x, y - robot.y) <= ROBOT_RADIUS_M) return;   // not on top of the robot
  request('spawn_box', {x: round3(x), y: round3(y)});
}

/** Moves the model on screen at once (the next world frame confirms), and back if the server refuses. */
function moveModel(model, px, py) {
  const [x, y] = pixelToOdom(px, py);
  const old = {x: model.x, y: model.y};
  model.x = round3(x);
  model.y = round3(y);
  const context = {model, old, x: model.x, y: model.y};
  if (request('move_model', {name: model.name, x: model.x, y: model.y}, context) === null) undoMove(context);
}

function undoMove(context) {
  if (context.model.x === context.x && context.model.y === context.y) {
    context.model.x = context.old.x;
    context.model.y = context.old.y;
    redraw('live');
  }
}

function deleteModel(name) {
  request('delete_model', {name});
  if (app.selectedModel === name) app.selectedModel = null;
  redraw('live');
}

function setup() {
  addLayer(10, drawScene);
  addLayer(20, drawModels);
  addLayer(30, drawOtherRobots);
  addLayer(60, drawDraggedModel);
  addVisibility(updateVisibility);
  canvas.addEventListener('mousedown', (event) => {
    if (event.button !== 0 || app.tool) return;   // a tool of the tools panel takes the press
    event.preventDefault();               // no text selection while dragging
    const point = canvasPoint(event);
    app.mouse = {start: point, current: point, model: modelAt(...point), dragging: false};
  });
  window.addEventListener('mousemove', (event) => {
    const m = app.mouse;
    if (!m) return;
    m.current = canvasPoint(event);
    const moved = Math.hypot(m.current[0] - m.start[0], m.current[1] - m.start[1]) > CLICK_SLOP_PX;
    if (m.model && (moved || m.dragging)) {
      m.dragging = true;
      canvas.style.cursor = 'grabbing';
      redraw('live');
    }
  });
  window.addEventListener('mouseup', (event) => {
    const m = app.mouse;
    if (!m || event.button !== 0) return;
    app.mouse = null;
    canvas.style.cursor = '';
    const end = canvasPoint(event);
    const moved = Math.hypot(end[0] - m.start[0], end[1] - m.start[1]) > CLICK_SLOP_PX;
    if (m.model && moved) {
      moveModel(m.model, end[0], end[1]);
    } else if (m.model) {
      app.selectedModel = m.model.name;   // selected: Delete removes it
    } else if (!moved) {
      app.selectedModel = null;
      spawnBox(m.start[0], m.start[1]);
    }
    redraw('live');
  });
  // Hover feedback: a hand over models, a crosshair over the floor.
  canvas.addEventListener('mousemove', (event) => {
    if (!app.mouse && !app.tool) canvas.style.cursor = modelAt(...canvasPoint(event)) ? 'grab' : '';
  });
  canvas.addEventListener('contextmenu', (event) => {
    const model = modelAt(...canvasPoint(event));
    if (!model) return;
    event.preventDefault();
    deleteModel(model.name);
  });
  window.addEventListener('keydown', (event) => {
    if (!isPageKey(event)) return;
    if (event.key === 'Delete' && app.selectedModel) {
      event.preventDefault();
      deleteModel(app.selectedModel);
    } else if (event.key === 'Escape' && app.mouse) {
      app.mouse = null;                   // cancel a drag
      redraw('live');
    }
  });
  $('reset-world').addEventListener('click', () => request('reset_world', {}));
}

function onHello() {
  app.world = null;
  app.scene = null;
  app.mouse = null;
  labView.models = [];
  labView.scenePrimitives = 0;
}

export default {
  name: 'world',
  setup,
  onHello,
  frames: {world: onWorld, scene: onScene},
  replies: {move_model: (reply, context) => { if (!reply.ok) undoMove(context); }},
};
