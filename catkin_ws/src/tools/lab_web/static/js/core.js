/*
 * core.js: what every page panel shares: the page state `app`, the test hooks `labView`, sending commands and
 * requests over the socket, the messages box, redraw scheduling and small DOM helpers. The frame and command
 * formats are documented in one place: `python3 -m lab_web.protocol` (built from the server panels).
 * It never logs to the console (tests treat console errors as failures): problems go to #messages.
 */

const MAX_MESSAGES = 5;
const MAX_LATENCIES = 500;

export const $ = (id) => document.getElementById(id);

/** The page's state, shared by the panels (each keeps to its own keys). Also window.app, a test hook. */
export const app = {
  socket: null,
  nextId: 1,
  pending: new Map(),        // request id -> what the request was, to act on its reply
  limits: {},                // hello.teleop_limits
  world: null,               // latest `world` frame
  scene: null,               // latest `scene` frame's primitives
  state: null,               // latest `state` frame
  trail: [],                 // robot path, kept from the incremental `state.trail` updates
  robotSeen: false,          // a state with a robot arrived: teleop drives "robot"
  turtlesim: null,           // latest `turtlesim` frame
  turtleImage: null,         // decoded pen canvas PNG
  view: null,                // world view transform; changes only with bounds (or a robot leaving it)
  mouse: null,               // box tool: the press in progress on the world canvas
  tool: null,                // the tools panel's tool in use (null: the default, moving boxes)
  fixed: null,               // latest `fixed` frame: the fixed frame and odom's pose in it
  selectedModel: null,
  selectedTopic: null,
  cameraOn: false,
  stateTimes: [],            // arrival times of state frames in the last second, for #fps
};

/** What tests read and call (the page's own state stays in `app`). */
export const labView = {
  connected: false,
  frames: 0,
  latenciesMs: [],
  replies: [],
  errors: [],
  robot: null,
  models: [],
  scenePrimitives: 0,        // how many scene primitives the latest scene frame brought
  sceneFrames: 0,            // how many scene frames came (one per page while the floor stays the same)
};
window.labView = labView;
window.app = app;

export function send(frame) {
  if (!app.socket || app.socket.readyState !== WebSocket.OPEN) return false;
  app.socket.send(JSON.stringify(frame));
  return true;
}

/** Sends a command that gets a `reply`; `context` is remembered until the reply arrives. */
export function request(type, args, context) {
  const id = app.nextId;
  app.nextId = app.nextId >= 2147483647 ? 1 : app.nextId + 1;
  if (!send(Object.assign({type, id}, args))) {
    addMessage(`${type}: not connected to the server`);
    return null;
  }
  app.pending.set(id, Object.assign({type}, context));
  return id;
}

export function recordLatency(stampMs) {
  if (!isNumber(stampMs)) return;
  labView.latenciesMs.push(Date.now() - stampMs);
  if (labView.latenciesMs.length > MAX_LATENCIES) labView.latenciesMs.splice(0, labView.latenciesMs.length - MAX_LATENCIES);
}

/* ============================================================ redraws and panel visibility */

const renderers = new Map();     // canvas name -> {draw, visible}
const dirty = new Set();
let renderQueued = false;

/** A canvas the page redraws on request: `draw()` runs on the next animation frame while `visible()`. */
export function addRenderer(name, draw, visible) {
  renderers.set(name, {draw, visible});
}

/** Marks a canvas as changed; it is redrawn once on the next animation frame, and only then. */
export function requestRender(which) {
  dirty.add(which);
  if (!renderQueued) {
    renderQueued = true;
    requestAnimationFrame(renderFrame);
  }
}

function renderFrame() {
  renderQueued = false;
  for (const [name, renderer] of renderers) {
    if (dirty.has(name) && renderer.visible()) {
      dirty.delete(name);
      renderer.draw();
    }
  }
}

const visibilityHooks = [];

/** `update()` shows or hides a panel's section and says whether it shows a simulator (the waiting note goes). */
export function addVisibility(update) {
  visibilityHooks.push(update);
}

/** Shows each simulator's view once there is one, and a waiting note before any. */
export function updatePanels() {
  let showing = false;
  for (const update of visibilityHooks) showing = update() || showing;
  $('waiting-panel').hidden = showing;
}

/* ============================================================ messages and small helpers */

/** Errors and refusals, newest first, at most MAX_MESSAGES lines: the page never uses alert() or the console. */
export function addMessage(text) {
  const messages = $('messages');
  const line = element('div', 'message', String(text));
  line.title = `at ${new Date().toLocaleTimeString([], {hour12: false})}`;   // the line itself is just the text
  messages.prepend(line);
  while (messages.children.length > MAX_MESSAGES) messages.lastElementChild.remove();
}

export function element(tag, className, text) {
  const el = document.createElement(tag);
  if (className) el.className = className;
  if (text) el.textContent = text;
  return el;
}

/** Writes text only when it differs, to spare layout work at 25 state frames per second. */
export function setText(el, text) {
  if (el.textContent !== text) el.textContent = text;
}

export function isNumber(value) {
  return typeof value === 'number' && Number.isFinite(value);
}

export function validRobot(robot) {
  return robot && isNumber(robot.x) && isNumber(robot.y) ? robot : null;
}

/** Keys typed into a form field are not commands for the page (checkboxes take no arrow keys). */
export function isTypingTarget(el) {
  if (!el || !el.tagName) return false;
  if (el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' || el.isContentEditable) return true;
  return el.tagName === 'INPUT' && !['checkbox', 'radio', 'button', 'submit', 'reset'].includes(el.type);
}

/** A key press meant for the page: not typed into a field, no modifier held. */
export function isPageKey(event) {
  return !isTypingTarget(event.target) && !event.ctrlKey && !event.altKey && !event.metaKey;
}

/** The bytes of base64 text, or null when it is not base64. */
export function base64Bytes(base64) {
  let text;
  try {
    text = atob(base64);
  } catch (err) {
    return null;
  }
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  return bytes;
}

/** The values of base64 little-endian float32 data (lab_web.packed), or null when it is not whole float32s. */
export function decodeFloat32(base64) {
  const bytes = typeof base64 === 'string' ? base64Bytes(base64) : null;
  return bytes && bytes.length % 4 === 0 ? new Float32Array(bytes.buffer) : null;
}

const decoding = new Map();      // key -> sequence number of the newest image asked for
const decoded = new Map();       // key -> the newest image delivered

/** Decodes a PNG given as base64 once and calls `done(image)` with an ImageBitmap, unless a newer one under `key`
 *  came meanwhile. createImageBitmap decodes off the page's main thread (an Image decodes where a canvas first
 *  draws it, in the middle of a frame). An image stays valid until the next one under its key is delivered, which
 *  frees it: decoded pixels live outside the JavaScript heap, where the garbage collector hardly feels them. */
export function decodePng(key, base64, done) {
  const seq = (decoding.get(key) || 0) + 1;
  decoding.set(key, seq);
  const bytes = typeof base64 === 'string' ? base64Bytes(base64) : null;
  const failed = () => addMessage(`could not decode the ${key} image`);
  if (!bytes) {
    failed();
    return;
  }
  createImageBitmap(new Blob([bytes], {type: 'image/png'})).then((image) => {
    if (decoding.get(key) !== seq) {
      image.close();
      return;
    }
    const old = decoded.get(key);
    decoded.set(key, image);
    done(image);
    if (old) old.close();
  }, failed);
}
