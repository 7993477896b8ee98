/*
 * app.js: the browser side of lab_web, the web view of the ROS 1 teaching lab.
 * One WebSocket (/ws on the page's own host) carries JSON text frames as described in
 * lab_web/protocol.py. This file draws tb3_sim's world and turtlesim on canvases, shows the
 * ROS graph, and sends teleop, box-tool and service commands. Plain ES2017, no libraries.
 * It never logs to the console (tests treat console errors as failures): problems go to #messages.
 */
'use strict';

/* ============================================================ constants */

const RECONNECT_MS = 1000;
const TELEOP_PERIOD_MS = 100;
const SPEED_FRACTION = 0.8;           // drive at 80 % of the server's limits, so never beyond them
const CLICK_SLOP_PX = 4;              // mouse travel up to this is a click, beyond it a drag
const VIEW_MARGIN_PX = 16;
const ROBOT_RADIUS_M = 0.15;
const TURTLE_PX = 500;                // turtlesim's pen canvas is 500 x 500 pixels
const DEFAULT_TURTLE_SIZE_M = 500 / 45; // turtlesim draws 45 px per metre: 11.08 m
const MAX_LATENCIES = 500;
const MAX_MESSAGES = 5;
const WEEK4_SERVICES = ['/move_service', '/timed_move_service', '/approach_service'];
const KEY_DIRECTIONS = {ArrowUp: 'forward', ArrowDown: 'back', ArrowLeft: 'left', ArrowRight: 'right'};
const INT_TYPE = /^(u?int(8|16|32|64)|byte|char)$/;
const FLOAT_TYPE = /^float(32|64)$/;
const COLORS = {
  floor: '#f4f4f0', grid: 'rgba(0, 0, 0, 0.07)', axis: 'rgba(0, 0, 0, 0.16)', static: '#555555',
  model: '#b07840', modelEdge: '#7d5226', otherRobot: 'rgba(20, 35, 110, 0.45)', robot: '#1f4ea3',
  heading: '#ffffff', trail: '#ff8c00', scan: '#e03030', selection: '#1f4ea3',
  turtle: '#2f9e44', turtleEdge: '#1b5e20',
};

/* ============================================================ DOM and page state */

const $ = (id) => document.getElementById(id);
const dom = {
  status: $('status'), simTime: $('sim-time'), rtf: $('rtf'), fps: $('fps'),
  waiting: $('waiting-panel'), worldPanel: $('world-panel'), world: $('world'),
  turtlePanel: $('turtlesim-panel'), turtle: $('turtlesim'), turtleHint: $('turtlesim-hint'),
  cameraToggle: $('camera-toggle'), cameraImg: $('camera-img'), cameraNote: $('camera-note'),
  teleopTarget: $('teleop-target'), teleopSpeeds: $('teleop-speeds'), resetWorld: $('reset-world'),
  serviceForm: $('service-form'), serviceName: $('service-name'), serviceFields: $('service-fields'),
  serviceReply: $('service-reply'), messages: $('messages'),
  topics: $('graph-topics'), nodes: $('graph-nodes'), services: $('graph-services'),
  topicCount: $('topic-count'), nodeCount: $('node-count'), serviceCount: $('service-count'),
  echo: $('echo'), echoTopic: $('echo-topic'),
};
// willReadFrequently: tests read pixels back with getImageData; without it Chromium warns in the console.
const worldCtx = dom.world.getContext('2d', {willReadFrequently: true});
const turtleCtx = dom.turtle.getContext('2d', {willReadFrequently: true});

const app = {
  socket: null,
  nextId: 1,
  pending: new Map(),        // request id -> what the request was, to act on its reply
  limits: {},                // hello.teleop_limits
  world: null,               // latest `world` frame
  state: null,               // latest `state` frame
  trail: [],                 // robot path, kept from the incremental `state.trail` updates
  robotSeen: false,          // a state with a robot arrived: teleop drives "robot"
  turtlesim: null,           // latest `turtlesim` frame
  turtleImage: null,         // decoded pen canvas PNG
  turtleImageSeq: 0,
  view: null,                // world view transform; changes only with bounds (or a robot leaving it)
  mouse: null,               // box tool: the press in progress on the world canvas
  selectedModel: null,
  selectedTopic: null,
  cameraOn: false,
  fieldsLoadedFor: null,     // service whose request fields are shown
  fieldsRetry: null,         // service whose fields failed while it was not running: retry once it appears
  listedServices: new Set(), // service names in the latest graph frame
  stateTimes: [],            // arrival times of state frames in the last second, for #fps
  held: {keys: new Set(), buttons: new Set()},
  teleopTimer: null,
  teleopMoving: false,       // a non-stop command went out since the last zeros
};

/* ============================================================ test hooks */

const labView = {
  connected: false,
  frames: 0,
  latenciesMs: [],
  worldToPixel,
  pixelToWorld,
  turtleToPixel,
  replies: [],
  errors: [],
  robot: null,
  models: [],
  scenePrimitives: 0,        // how many scene primitives the latest world frame brought
};
window.labView = labView;

/* ============================================================ connection */

function socketUrl() {
  const token = new URLSearchParams(location.search).get('token');
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/ws` + (token === null ? '' : `?token=${encodeURIComponent(token)}`);
}

function connect() {
  const socket = new WebSocket(socketUrl());
  app.socket = socket;
  socket.addEventListener('open', () => {
    setConnected(true);
    restoreSubscriptions();
  });
  socket.addEventListener('message', (event) => handleFrameText(event.data));
  // 'error' is always followed by 'close', which does the reconnecting.
  socket.addEventListener('close', () => {
    if (app.socket !== socket) return;
    app.socket = null;
    app.pending.clear();     // replies to requests on the old socket never come
    setConnected(false);
    setTimeout(connect, RECONNECT_MS);
  });
}

function setConnected(on) {
  labView.connected = on;
  dom.status.textContent = on ? 'connected' : 'disconnected';
  dom.status.classList.toggle('on', on);
  dom.status.classList.toggle('off', !on);
}

/** The server keeps no per-page memory across reconnects: ask again for what this page shows. */
function restoreSubscriptions() {
  if (app.selectedTopic) send({type: 'echo', topic: app.selectedTopic});
  if (app.cameraOn && !document.hidden) send({type: 'camera', on: true});
  if (app.fieldsLoadedFor !== dom.serviceName.value) loadServiceFields();
}

function send(frame) {
  if (!app.socket || app.socket.readyState !== WebSocket.OPEN) return false;
  app.socket.send(JSON.stringify(frame));
  return true;
}

/** Sends a command that gets a `reply`; `context` is remembered until the reply arrives. */
function request(type, args, context) {
  const id = app.nextId;
  app.nextId = app.nextId >= 2147483647 ? 1 : app.nextId + 1;
  if (!send(Object.assign({type, id}, args))) {
    addMessage(`${type}: not connected to the server`);
    return null;
  }
  app.pending.set(id, Object.assign({type}, context));
  return id;
}

const FRAME_HANDLERS = {
  hello: onHello, world: onWorld, state: onState, turtlesim: onTurtlesim, canvas: onCanvas,
  camera: onCamera, graph: onGraph, echo: onEcho, reply: onReply, error: onError,
};

function handleFrameText(text) {
  let frame;
  try {
    frame = JSON.parse(text);
  } catch (err) {
    addMessage('the server sent a frame that is not JSON');
    return;
  }
  const handler = frame && FRAME_HANDLERS[frame.type];
  if (!handler) return;      // unknown types are ignored, so a newer server does not break the page
  try {
    handler(frame);
  } catch (err) {
    addMessage(`could not show a "${frame.type}" frame: ${err.message}`);
  }
}

/* ============================================================ incoming frames */

function onHello(frame) {
  if (frame.version !== 1) addMessage(`server protocol version ${frame.version}, this page knows version 1`);
  app.limits = frame.teleop_limits || {};
  // A new session (maybe a restarted server running other simulators): forget what the old one showed.
  app.world = null;
  app.state = null;
  app.trail = [];
  app.robotSeen = false;
  app.turtlesim = null;
  app.turtleImage = null;
  app.mouse = null;
  labView.robot = null;
  labView.models = [];
  updateTeleopInfo();
  updatePanels();
}

function onWorld(frame) {
  app.world = frame;
  labView.models = Array.isArray(frame.models) ? frame.models : [];
  labView.scenePrimitives = Array.isArray(frame.scene) ? frame.scene.length : 0;
  if (app.selectedModel && !findModel(app.selectedModel)) app.selectedModel = null;
  if (app.mouse && app.mouse.model && !findModel(app.mouse.model.name)) app.mouse = null;
  updateView();
  updatePanels();
  requestRender('world');
}

/** The server sends the trail incrementally: reset replaces the page's copy, otherwise points are appended. */
const TRAIL_MAX_POINTS = 3000;
function updateTrail(update) {
  if (!update || !Array.isArray(update.points)) return;
  app.trail = update.reset ? update.points.slice() : app.trail.concat(update.points);
  if (app.trail.length > TRAIL_MAX_POINTS) app.trail = app.trail.slice(app.trail.length - TRAIL_MAX_POINTS);
}

function onState(frame) {
  app.state = frame;
  updateTrail(frame.trail);
  labView.frames += 1;
  labView.robot = frame.robot || null;
  recordLatency(frame.stamp_ms);
  app.stateTimes.push(performance.now());
  if (frame.robot && !app.robotSeen) {
    app.robotSeen = true;
    updateTeleopInfo();
    updatePanels();
  }
  setText(dom.simTime, isNumber(frame.sim_time) ? frame.sim_time.toFixed(1) : '—');
  setText(dom.rtf, isNumber(frame.rtf) ? `${frame.rtf.toFixed(2)}x` : '—');
  updateView();
  requestRender('world');
}

function onTurtlesim(frame) {
  const first = !app.turtlesim;
  app.turtlesim = frame;
  recordLatency(frame.stamp_ms);
  if (!app.robotSeen) app.stateTimes.push(performance.now());   // #fps counts turtlesim frames without a robot
  dom.turtleHint.hidden = frame.canvas !== false;
  if (first) {
    updateTeleopInfo();
    updatePanels();
  }
  requestRender('turtle');
}

/** Decodes each pen canvas PNG once; frames are drawn from the decoded image. */
function onCanvas(frame) {
  const seq = ++app.turtleImageSeq;
  const image = new Image();
  image.onload = () => {
    if (seq !== app.turtleImageSeq) return;   // a newer canvas arrived while this one decoded
    app.turtleImage = image;
    requestRender('turtle');
  };
  image.onerror = () => addMessage('could not decode the turtlesim canvas image');
  image.src = `data:image/png;base64,${frame.png}`;
}

function onCamera(frame) {
  if (!app.cameraOn) return;     // a frame that was on its way when the camera was switched off
  dom.cameraImg.src = `data:image/jpeg;base64,${frame.jpeg}`;
  dom.cameraImg.hidden = false;
  dom.cameraNote.hidden = true;
}

function onEcho(frame) {
  if (frame.topic !== app.selectedTopic) return;
  dom.echo.textContent = frame.text;
}

function onReply(frame) {
  const reply = {id: frame.id, ok: frame.ok === true, text: String(frame.text)};
  labView.replies.push(reply);
  const context = app.pending.get(reply.id);
  app.pending.delete(reply.id);
  // A form asking for a service that is not running yet says so in its own reply box, not as an error.
  if (!reply.ok && !(context && context.type === 'service_fields')) addMessage(reply.text);
  if (!context) return;
  if (context.type === 'service_fields') showServiceFields(context.service, reply);
  else if (context.type === 'call_service') showServiceReply(reply);
  else if (context.type === 'move_model' && !reply.ok) undoMove(context);
}

function onError(frame) {
  const text = String(frame.text);
  labView.errors.push(text);
  addMessage(text);
}

function recordLatency(stampMs) {
  if (!isNumber(stampMs)) return;
  labView.latenciesMs.push(Date.now() - stampMs);
  if (labView.latenciesMs.length > MAX_LATENCIES) labView.latenciesMs.splice(0, labView.latenciesMs.length - MAX_LATENCIES);
}

/** Frames per second of state frames, counted over the last second. */
function updateFps() {
  const now = performance.now();
  while (app.stateTimes.length && now - app.stateTimes[0] > 1000) app.stateTimes.shift();
  setText(dom.fps, String(app.stateTimes.length));
}

/** Shows the tb3 world once there is one, turtlesim once it speaks, and a waiting note before either. */
function updatePanels() {
  const w = app.world;
  const hasWorld = app.robotSeen || Boolean(w && ((w.static || []).length || (w.models || []).length || (w.robots || []).length));
  const worldWasHidden = dom.worldPanel.hidden;
  dom.worldPanel.hidden = !hasWorld;
  dom.turtlePanel.hidden = !app.turtlesim;
  dom.waiting.hidden = hasWorld || Boolean(app.turtlesim);
  if (worldWasHidden && hasWorld) requestRender('world');
}

/* ============================================================ rendering: scheduling */

const dirty = {world: false, turtle: false};
let renderQueued = false;

/** Marks a canvas as changed; it is redrawn once on the next animation frame, and only then. */
function requestRender(which) {
  dirty[which] = true;
  if (!renderQueued) {
    renderQueued = true;
    requestAnimationFrame(renderFrame);
  }
}

function renderFrame() {
  renderQueued = false;
  if (dirty.world && !dom.worldPanel.hidden) {
    dirty.world = false;
    drawWorld();
  }
  if (dirty.turtle && app.turtlesim) {
    dirty.turtle = false;
    drawTurtlesim();
  }
}

/* ============================================================ world view transform */

function validBounds(world) {
  const b = world && world.bounds;
  if (!Array.isArray(b) || b.length !== 4 || !b.every(isNumber) || b[2] <= b[0] || b[3] <= b[1]) return null;
  return b;
}

function fitRegion(region, key) {
  const width = Math.max(region[2] - region[0], 0.1);
  const height = Math.max(region[3] - region[1], 0.1);
  const scale = Math.min((dom.world.width - 2 * VIEW_MARGIN_PX) / width, (dom.world.height - 2 * VIEW_MARGIN_PX) / height);
  return {key, region, scale, cx: (region[0] + region[2]) / 2, cy: (region[1] + region[3]) / 2};
}

function currentView() {
  if (!app.view) app.view = fitRegion([-5, -5, 5, 5], null);
  return app.view;
}

/** Refits only when the bounds change, or when the robot would be drawn outside the canvas. */
function updateView() {
  const bounds = validBounds(app.world);
  const robot = validRobot(app.state && app.state.robot);
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
  return px - r >= 0 && py - r >= 0 && px + r <= dom.world.width && py + r <= dom.world.height;
}

function worldToPixel(x, y) {
  const v = currentView();
  return [dom.world.width / 2 + (x - v.cx) * v.scale, dom.world.height / 2 - (y - v.cy) * v.scale];
}

function pixelToWorld(px, py) {
  const v = currentView();
  return [v.cx + (px - dom.world.width / 2) / v.scale, v.cy - (py - dom.world.height / 2) / v.scale];
}

/* ============================================================ world rendering */

function drawWorld() {
  const ctx = worldCtx;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.globalAlpha = 1;
  ctx.fillStyle = COLORS.floor;
  ctx.fillRect(0, 0, dom.world.width, dom.world.height);
  drawGrid(ctx);
  const world = app.world || {};
  // The floor layer and static shapes as tb3_sim's scene primitives; the markers' shapes where none came.
  if (Array.isArray(world.scene)) drawPrimitives(ctx, world.scene);
  else for (const shape of world.static || []) drawShape(ctx, shape);
  for (const model of world.models || []) drawModel(ctx, model);
  // world.robots (2 Hz) includes the driven robot too, drawn from /odom below: only the others are drawn here.
  const own = (app.state || {}).robot;
  const OWN_ROBOT_RADIUS_M = 0.35;
  for (const robot of world.robots || []) {
    if (own && Math.hypot(robot.x - own.x, robot.y - own.y) < OWN_ROBOT_RADIUS_M) continue;
    drawBody(ctx, robot, robot.x, robot.y, COLORS.otherRobot);
  }
  const state = app.state || {};
  drawTrail(ctx, app.trail);
  drawScan(ctx, state.scan || []);
  drawDraggedModel(ctx);
  const robot = validRobot(state.robot);
  if (robot) drawRobot(ctx, robot);     // last: always on top
}

/** A faint 1 m grid, with the x and y axes a little darker; skipped when lines would crowd. */
function drawGrid(ctx) {
  const scale = currentView().scale;
  if (scale < 6) return;
  const [x0, y1] = pixelToWorld(0, 0);
  const [x1, y0] = pixelToWorld(dom.world.width, dom.world.height);
  ctx.lineWidth = 1;
  for (let gx = Math.ceil(x0); gx <= x1; gx++) {
    const px = Math.round(worldToPixel(gx, 0)[0]) + 0.5;
    strokeLine(ctx, px, 0, px, dom.world.height, gx === 0 ? COLORS.axis : COLORS.grid);
  }
  for (let gy = Math.ceil(y0); gy <= y1; gy++) {
    const py = Math.round(worldToPixel(0, gy)[1]) + 0.5;
    strokeLine(ctx, 0, py, dom.world.width, py, gy === 0 ? COLORS.axis : COLORS.grid);
  }
}

function strokeLine(ctx, ax, ay, bx, by, color) {
  ctx.strokeStyle = color;
  ctx.beginPath();
  ctx.moveTo(ax, ay);
  ctx.lineTo(bx, by);
  ctx.stroke();
}

function tracePath(ctx, points) {
  ctx.beginPath();
  points.forEach((point, i) => {
    const [px, py] = worldToPixel(point[0], point[1]);
    if (i === 0) ctx.moveTo(px, py);
    else ctx.lineTo(px, py);
  });
}

/* Scene primitives (tb3_sim.core.primitives, sent as data in the world frame): one drawer per kind, so the page
   draws every kind of floor marking without knowing any. Units are metres, colours [r, g, b]. */
const CAP_HEIGHT_PER_EM = 0.73;   // DejaVu Sans: a Text's height is its cap height
const sceneImages = new Map();    // data URL -> HTMLImageElement

/** A primitive's colour; none (a wall the world file gave no colour) is the page's wall colour. */
function rgbText(rgb) {
  return Array.isArray(rgb) ? `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})` : COLORS.static;
}

function sceneImage(src) {
  if (!sceneImages.has(src)) {
    const image = new Image();
    image.onload = () => requestRender('world');
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

function drawPrimitives(ctx, primitives) {
  for (const primitive of primitives) {
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

/** A box or circle model at (x, y), keeping its own yaw. */
function drawBody(ctx, body, x, y, fill, edge) {
  const [px, py] = worldToPixel(x, y);
  const s = currentView().scale;
  ctx.save();
  ctx.translate(px, py);
  ctx.rotate(-(body.yaw || 0));       // the canvas y axis points down, so angles turn the other way
  ctx.beginPath();
  if (body.kind === 'circle') ctx.arc(0, 0, Math.max(body.r * s, 2), 0, 2 * Math.PI);
  else ctx.rect(-body.sx * s / 2, -body.sy * s / 2, body.sx * s, body.sy * s);
  ctx.fillStyle = fill;
  ctx.fill();
  if (edge) {
    ctx.lineWidth = edge.width || 1;
    ctx.strokeStyle = edge.color;
    ctx.setLineDash(edge.dash || []);
    ctx.stroke();
  }
  ctx.restore();
}

function drawModel(ctx, model) {
  const dragged = app.mouse && app.mouse.dragging && app.mouse.model === model;
  ctx.globalAlpha = dragged ? 0.3 : 1;     // its old place stays faintly visible while dragging
  const selected = model.name === app.selectedModel;
  drawBody(ctx, model, model.x, model.y, COLORS.model,
    selected ? {color: COLORS.selection, width: 2, dash: [4, 3]} : {color: COLORS.modelEdge});
  ctx.globalAlpha = 1;
}

function drawDraggedModel(ctx) {
  const m = app.mouse;
  if (!m || !m.dragging) return;
  const [x, y] = pixelToWorld(m.current[0], m.current[1]);
  drawBody(ctx, m.model, x, y, COLORS.model, {color: COLORS.selection, width: 2});
}

function drawTrail(ctx, trail) {
  if (trail.length < 2) return;
  tracePath(ctx, trail);
  ctx.lineWidth = 2;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = COLORS.trail;
  ctx.stroke();
}

/** 2 x 2 px dots on whole pixels, covering both the rounded and the truncated pixel of each hit. */
function drawScan(ctx, scan) {
  ctx.fillStyle = COLORS.scan;
  for (const hit of scan) {
    const [px, py] = worldToPixel(hit[0], hit[1]);
    ctx.fillRect(Math.round(px) - 1, Math.round(py) - 1, 2, 2);
  }
}

function drawRobot(ctx, robot) {
  const [px, py] = worldToPixel(robot.x, robot.y);
  const r = Math.max(ROBOT_RADIUS_M * currentView().scale, 4);
  ctx.beginPath();
  ctx.arc(px, py, r, 0, 2 * Math.PI);
  ctx.fillStyle = COLORS.robot;
  ctx.fill();
  strokeHeading(ctx, px, py, r, robot.yaw || 0);
}

function strokeHeading(ctx, px, py, r, yaw) {
  ctx.lineWidth = 2;
  ctx.lineCap = 'butt';
  strokeLine(ctx, px, py, px + r * Math.cos(yaw), py - r * Math.sin(yaw), COLORS.heading);
}

/* ============================================================ turtlesim rendering */

function turtleToPixel(x, y) {
  const size = (app.turtlesim && isNumber(app.turtlesim.size_m) && app.turtlesim.size_m > 0)
    ? app.turtlesim.size_m : DEFAULT_TURTLE_SIZE_M;
  return [x * TURTLE_PX / size, TURTLE_PX - y * TURTLE_PX / size];
}

function drawTurtlesim() {
  const ctx = turtleCtx;
  const ts = app.turtlesim;
  const bg = Array.isArray(ts.background) ? ts.background : [69, 86, 255];
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = `rgb(${bg[0]}, ${bg[1]}, ${bg[2]})`;
  ctx.fillRect(0, 0, TURTLE_PX, TURTLE_PX);
  // Without ~publish_canvas the last image would be stale (turtlesim restarted): draw only live ones.
  if (app.turtleImage && ts.canvas !== false) ctx.drawImage(app.turtleImage, 0, 0, TURTLE_PX, TURTLE_PX);
  for (const turtle of ts.turtles || []) drawTurtle(ctx, turtle);
}

/** A small turtle seen from above: shell, head in front (along theta), four legs. */
function drawTurtle(ctx, turtle) {
  const [px, py] = turtleToPixel(turtle.x, turtle.y);
  ctx.save();
  ctx.translate(px, py);
  ctx.rotate(-(turtle.theta || 0));
  ctx.scale(1.3, 1.3);
  ctx.fillStyle = COLORS.turtle;
  ctx.strokeStyle = COLORS.turtleEdge;
  ctx.lineWidth = 1.5;
  for (const [lx, ly] of [[6, 8], [6, -8], [-6, 8], [-6, -8]]) {
    ctx.beginPath();
    ctx.arc(lx, ly, 3.5, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  }
  ctx.beginPath();
  ctx.arc(14, 0, 4.5, 0, 2 * Math.PI);      // head
  ctx.fill();
  ctx.stroke();
  ctx.beginPath();
  ctx.moveTo(-12, 0);                         // tail
  ctx.lineTo(-17, 0);
  ctx.stroke();
  ctx.beginPath();
  ctx.ellipse(0, 0, 11, 8.5, 0, 0, 2 * Math.PI);   // shell
  ctx.fill();
  ctx.stroke();
  ctx.restore();
}

/* ============================================================ graph panel */

function onGraph(frame) {
  const nodes = (frame.nodes || []).slice().sort();
  const topics = (frame.topics || []).slice().sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  const services = (frame.services || []).slice().sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  renderNameList(dom.nodes, nodes.map((name) => [name, '']));
  renderNameList(dom.services, services.map((s) => [s.name, s.node || '']));
  renderTopics(topics);
  setText(dom.nodeCount, `(${nodes.length})`);
  setText(dom.topicCount, `(${topics.length})`);
  setText(dom.serviceCount, `(${services.length})`);
  addServiceOptions(services);
  app.listedServices = new Set(services.map((s) => s.name));
  if (app.fieldsRetry === dom.serviceName.value && app.listedServices.has(app.fieldsRetry)) {
    app.fieldsRetry = null;
    loadServiceFields();
  }
}

/** Rebuilds a name list only when its content changed (the graph repeats every 2 s). */
function renderNameList(list, entries) {
  const key = JSON.stringify(entries);
  if (list.dataset.key === key) return;
  list.dataset.key = key;
  list.replaceChildren(...entries.map(([name, note]) => {
    const item = document.createElement('li');
    item.textContent = name;
    if (note) item.appendChild(element('span', 'subtle', note));
    return item;
  }));
}

/** Updates topic rows in place (not rebuilt), so a click that lands during an update still counts. */
function renderTopics(topics) {
  const rows = new Map(Array.from(dom.topics.rows, (row) => [row.dataset.topic, row]));
  topics.forEach((topic, index) => {
    let row = rows.get(topic.name);
    rows.delete(topic.name);
    if (!row) row = createTopicRow(topic.name);
    setText(row.cells[1], topic.type || '');
    setText(row.cells[2], isNumber(topic.hz) ? `${topic.hz.toFixed(1)} Hz` : '—');
    setText(row.cells[3], (topic.publishers || []).join(', '));
    row.title = `subscribers: ${(topic.subscribers || []).join(', ') || 'none'}`;
    row.classList.toggle('selected', topic.name === app.selectedTopic);
    if (dom.topics.rows[index] !== row) dom.topics.insertBefore(row, dom.topics.rows[index] || null);
  });
  for (const stale of rows.values()) stale.remove();
}

function createTopicRow(name) {
  const row = document.createElement('tr');
  row.dataset.topic = name;
  row.tabIndex = 0;
  row.append(element('td', '', name), element('td', 'type', ''), element('td', 'num', ''), element('td', '', ''));
  return row;
}

function toggleTopic(name) {
  app.selectedTopic = app.selectedTopic === name ? null : name;
  for (const row of dom.topics.rows) row.classList.toggle('selected', row.dataset.topic === app.selectedTopic);
  dom.echo.textContent = '';
  dom.echo.classList.toggle('waiting', Boolean(app.selectedTopic));
  setText(dom.echoTopic, app.selectedTopic || '');
  send({type: 'echo', topic: app.selectedTopic});
}

function setupGraphPanel() {
  dom.topics.addEventListener('click', (event) => {
    const row = event.target.closest('tr[data-topic]');
    if (row) toggleTopic(row.dataset.topic);
  });
  dom.topics.addEventListener('keydown', (event) => {
    const row = event.target.closest('tr[data-topic]');
    if (row && (event.key === 'Enter' || event.key === ' ')) {
      event.preventDefault();
      toggleTopic(row.dataset.topic);
    }
  });
}

/* ============================================================ controls: teleop */

function teleopTarget() {
  if (app.robotSeen) return 'robot';
  if (app.turtlesim) return 'turtle1';
  return null;
}

/** [linear m/s, angular rad/s] for a target; hello names turtlesim's limits "turtle", commands say "turtle1". */
function limitsFor(target) {
  const limits = app.limits[target] || (target === 'turtle1' ? app.limits.turtle : null);
  if (!Array.isArray(limits) || limits.length < 2 || !isNumber(limits[0]) || !isNumber(limits[1])) return null;
  return [Math.abs(limits[0]), Math.abs(limits[1])];
}

function heldDirections() {
  return new Set([...app.held.keys, ...app.held.buttons]);
}

function sendTeleop(linear, angular) {
  const target = teleopTarget();
  const limits = limitsFor(target);
  if (!target || !limits) return;
  const clamp = (value, limit) => Math.max(-limit, Math.min(limit, value));
  send({type: 'teleop', target, linear: clamp(linear * limits[0], limits[0]), angular: clamp(angular * limits[1], limits[1])});
}

/** The held keys and buttons as a command in units of the limits (each within +-SPEED_FRACTION). */
function sendHeldCommand() {
  const held = heldDirections();
  const linear = (held.has('forward') ? 1 : 0) - (held.has('back') ? 1 : 0);
  const angular = (held.has('left') ? 1 : 0) - (held.has('right') ? 1 : 0);
  sendTeleop(SPEED_FRACTION * linear, SPEED_FRACTION * angular);
  app.teleopMoving = true;
}

function sendZeros() {
  sendTeleop(0, 0);
  app.teleopMoving = false;
}

/** Called whenever the set of held keys/buttons changes: send now, then every 100 ms, zeros once at the end. */
function teleopChanged() {
  clearInterval(app.teleopTimer);
  app.teleopTimer = null;
  for (const button of document.querySelectorAll('.drive-btn[data-drive]')) {
    button.classList.toggle('held', heldDirections().has(button.dataset.drive));
  }
  if (heldDirections().size) {
    sendHeldCommand();
    app.teleopTimer = setInterval(sendHeldCommand, TELEOP_PERIOD_MS);
  } else if (app.teleopMoving) {
    sendZeros();
  }
}

/** Page hidden, window unfocused, unloading: nothing is held any more (keyup would never come). */
function releaseAll() {
  app.held.keys.clear();
  app.held.buttons.clear();
  teleopChanged();
}

function updateTeleopInfo() {
  const target = teleopTarget();
  const limits = limitsFor(target);
  setText(dom.teleopTarget, target || 'nothing to drive yet');
  setText(dom.teleopSpeeds, limits
    ? `${(SPEED_FRACTION * limits[0]).toFixed(2)} m/s, ${(SPEED_FRACTION * limits[1]).toFixed(2)} rad/s` : '');
}

/** Keys typed into a form field are not driving commands (checkboxes take no arrow keys). */
function isTypingTarget(el) {
  if (!el || !el.tagName) return false;
  if (el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' || el.isContentEditable) return true;
  return el.tagName === 'INPUT' && !['checkbox', 'radio', 'button', 'submit', 'reset'].includes(el.type);
}

function setupTeleop() {
  window.addEventListener('keydown', (event) => {
    if (isTypingTarget(event.target) || event.ctrlKey || event.altKey || event.metaKey) return;
    const direction = KEY_DIRECTIONS[event.key];
    if (direction) {
      event.preventDefault();             // arrows drive; they must not scroll the page
      if (!app.held.keys.has(direction)) {
        app.held.keys.add(direction);
        teleopChanged();
      }
    } else if (event.key === 'Delete' && app.selectedModel) {
      event.preventDefault();
      deleteModel(app.selectedModel);
    } else if (event.key === 'Escape' && app.mouse) {
      app.mouse = null;                   // cancel a drag
      requestRender('world');
    }
  });
  window.addEventListener('keyup', (event) => {
    const direction = KEY_DIRECTIONS[event.key];
    if (!direction) return;
    if (!isTypingTarget(event.target)) event.preventDefault();
    if (app.held.keys.delete(direction)) teleopChanged();
  });
  for (const button of document.querySelectorAll('.drive-btn[data-drive]')) {
    const direction = button.dataset.drive;
    const release = () => {
      if (app.held.buttons.delete(direction)) teleopChanged();
    };
    button.addEventListener('pointerdown', (event) => {
      if (event.button !== 0) return;
      event.preventDefault();
      app.held.buttons.add(direction);
      teleopChanged();
    });
    button.addEventListener('pointerup', release);
    button.addEventListener('pointerleave', release);
    button.addEventListener('pointercancel', release);
    button.addEventListener('contextmenu', (event) => event.preventDefault());  // touch long-press
  }
  $('drive-stop').addEventListener('click', () => {
    app.held.keys.clear();
    app.held.buttons.clear();
    teleopChanged();
    sendZeros();                          // explicit stop: always send, even when nothing was held
  });
  window.addEventListener('blur', releaseAll);
  window.addEventListener('beforeunload', releaseAll);
  window.addEventListener('pagehide', () => {
    releaseAll();
    send({type: 'camera', on: false});
  });
  document.addEventListener('visibilitychange', () => {
    if (document.hidden) releaseAll();
    // No thumbnails for a hidden page; ask again when it shows.
    if (app.cameraOn) send({type: 'camera', on: !document.hidden});
  });
}

/* ============================================================ controls: box tool, reset, camera */

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
  const [x, y] = pixelToWorld(px, py);
  const tolerance = 3 / currentView().scale;
  const models = labView.models;
  for (let i = models.length - 1; i >= 0; i--) {
    if (hitsBody(models[i], x, y, tolerance)) return models[i];
  }
  return null;
}

function canvasPoint(event) {
  const rect = dom.world.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

const round3 = (value) => Math.round(value * 1000) / 1000;

function spawnBox(px, py) {
  const [x, y] = pixelToWorld(px, py);
  const robot = validRobot(app.state && app.state.robot);
  if (robot && Math.hypot(x - robot.x, y - robot.y) <= ROBOT_RADIUS_M) return;   // not on top of the robot
  request('spawn_box', {x: round3(x), y: round3(y)});
}

/** Moves the model on screen at once (the next world frame confirms), and back if the server refuses. */
function moveModel(model, px, py) {
  const [x, y] = pixelToWorld(px, py);
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
    requestRender('world');
  }
}

function deleteModel(name) {
  request('delete_model', {name});
  if (app.selectedModel === name) app.selectedModel = null;
  requestRender('world');
}

function setupBoxTool() {
  dom.world.addEventListener('mousedown', (event) => {
    if (event.button !== 0) return;
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
      dom.world.style.cursor = 'grabbing';
      requestRender('world');
    }
  });
  window.addEventListener('mouseup', (event) => {
    const m = app.mouse;
    if (!m || event.button !== 0) return;
    app.mouse = null;
    dom.world.style.cursor = '';
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
    requestRender('world');
  });
  // Hover feedback: a hand over models, a crosshair over the floor.
  dom.world.addEventListener('mousemove', (event) => {
    if (!app.mouse) dom.world.style.cursor = modelAt(...canvasPoint(event)) ? 'grab' : '';
  });
  dom.world.addEventListener('contextmenu', (event) => {
    const model = modelAt(...canvasPoint(event));
    if (!model) return;
    event.preventDefault();
    deleteModel(model.name);
  });
  dom.resetWorld.addEventListener('click', () => request('reset_world', {}));
}

function setupCamera() {
  dom.cameraToggle.checked = false;       // browsers may restore a checked box on reload
  dom.cameraToggle.addEventListener('change', () => {
    app.cameraOn = dom.cameraToggle.checked;
    send({type: 'camera', on: app.cameraOn});
    dom.cameraNote.hidden = !app.cameraOn;
    if (!app.cameraOn) {
      dom.cameraImg.hidden = true;
      dom.cameraImg.removeAttribute('src');
    }
  });
}

/* ============================================================ service form */

function addServiceOptions(services) {
  const known = new Set(Array.from(dom.serviceName.options, (option) => option.value));
  let group = dom.serviceName.querySelector('optgroup');
  for (const {name} of services) {
    if (typeof name !== 'string' || known.has(name)) continue;
    if (name.startsWith('/gazebo/') || name.includes('/get_loggers') || name.includes('/set_logger_level')) continue;
    if (!group) {
      group = document.createElement('optgroup');
      group.label = 'Other services';
      dom.serviceName.appendChild(group);
    }
    const option = element('option', '', name);
    option.value = name;
    group.appendChild(option);
    known.add(name);
  }
}

function loadServiceFields() {
  const service = dom.serviceName.value;
  app.fieldsLoadedFor = null;
  dom.serviceFields.replaceChildren();
  clearServiceReply();
  request('service_fields', {service}, {service});
}

function showServiceFields(service, reply) {
  if (service !== dom.serviceName.value) return;     // the selection changed meanwhile
  let fields = null;
  if (reply.ok) {
    try {
      fields = JSON.parse(reply.text);
    } catch (err) {
      fields = null;
    }
  }
  if (!Array.isArray(fields)) {
    // A student often starts the server after opening the page: ask again once the graph lists it.
    app.fieldsRetry = app.listedServices.has(service) ? null : service;
    dom.serviceReply.classList.add('failed');
    dom.serviceReply.textContent = reply.text;
    return;
  }
  app.fieldsLoadedFor = service;
  dom.serviceFields.replaceChildren();
  if (!fields.length) dom.serviceFields.appendChild(element('p', 'note', 'This service takes no request fields.'));
  for (const field of fields) dom.serviceFields.append(...fieldInput(field));
}

/** A label and an input for one request field, the input kind chosen from its ROS type. */
function fieldInput(field) {
  const id = `field-${field.name}`;
  const label = element('label', '', field.name);
  label.htmlFor = id;
  label.appendChild(element('span', 'type', field.type));
  const input = document.createElement('input');
  input.id = id;
  input.name = field.name;
  input.dataset.type = field.type;
  if (field.type === 'bool') {
    input.type = 'checkbox';
  } else if (FLOAT_TYPE.test(field.type) || INT_TYPE.test(field.type)) {
    input.type = 'number';
    input.step = FLOAT_TYPE.test(field.type) ? 'any' : '1';
    input.value = '0';
  } else {
    input.type = 'text';
    input.maxLength = 256;
  }
  return [label, input];
}

/** The form's values as JSON: bool -> true/false, numbers -> Number, strings as typed; null if one is bad. */
function collectFields() {
  const fields = {};
  for (const input of dom.serviceFields.querySelectorAll('input[name]')) {
    const type = input.dataset.type;
    if (type === 'bool') {
      fields[input.name] = input.checked;
    } else if (input.type === 'number') {
      const value = input.value.trim() === '' ? 0 : Number(input.value);
      if (input.validity.badInput || !Number.isFinite(value)) {
        showServiceReply({ok: false, text: `${input.name} must be a number`});
        return null;
      }
      fields[input.name] = value;
    } else {
      fields[input.name] = input.value;
    }
  }
  return fields;
}

function callService() {
  const fields = collectFields();
  if (!fields) return;
  const service = dom.serviceName.value;
  clearServiceReply();
  if (request('call_service', {service, fields}, {service}) !== null) dom.serviceReply.classList.add('pending');
}

function clearServiceReply() {
  dom.serviceReply.textContent = '';
  dom.serviceReply.classList.remove('failed', 'pending');
}

function showServiceReply(reply) {
  dom.serviceReply.classList.remove('pending');
  dom.serviceReply.classList.toggle('failed', !reply.ok);
  dom.serviceReply.textContent = reply.ok ? reply.text : `error: ${reply.text}`;
}

function setupServiceForm() {
  dom.serviceName.addEventListener('change', loadServiceFields);
  dom.serviceForm.addEventListener('submit', (event) => {
    event.preventDefault();
    callService();
  });
}

/* ============================================================ messages and small helpers */

/** Errors and refusals, newest first, at most MAX_MESSAGES lines: the page never uses alert() or the console. */
function addMessage(text) {
  const line = element('div', 'message', String(text));
  line.title = `at ${new Date().toLocaleTimeString([], {hour12: false})}`;   // the line itself is just the text
  dom.messages.prepend(line);
  while (dom.messages.children.length > MAX_MESSAGES) dom.messages.lastElementChild.remove();
}

function element(tag, className, text) {
  const el = document.createElement(tag);
  if (className) el.className = className;
  if (text) el.textContent = text;
  return el;
}

/** Writes text only when it differs, to spare layout work at 25 state frames per second. */
function setText(el, text) {
  if (el.textContent !== text) el.textContent = text;
}

function isNumber(value) {
  return typeof value === 'number' && Number.isFinite(value);
}

function validRobot(robot) {
  return robot && isNumber(robot.x) && isNumber(robot.y) ? robot : null;
}

/* ============================================================ start */

setupGraphPanel();
setupTeleop();
setupBoxTool();
setupCamera();
setupServiceForm();
setInterval(updateFps, 500);
connect();
