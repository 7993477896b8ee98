/*
 * app.js: the browser side of lab_web, the web view of the ROS 1 teaching lab (an ES module, no libraries).
 * One WebSocket (/ws on the page's own host) carries JSON text frames; `python3 -m lab_web.protocol` prints
 * them all. Each panel is one module under js/panels/ (set-up, frame handlers, drawing) matching one server
 * panel (lab_web/panels/); the server's `hello` names the panels, in order, and this file imports each one's
 * module by that name, connects, hands each frame to the panels that handle its type, and routes replies to the
 * panel whose request it answers. Adding a panel: its server module, its name in lab_web.panels.PANEL_NAMES and
 * its page module js/panels/<name>.js (nothing here).
 */
import {$, addMessage, app, labView, updatePanels} from './js/core.js';

const RECONNECT_MS = 1000;
const PANEL_NAME = /^[a-z][a-z0-9_]*$/;

const panels = new Map();                                                  // name -> page module, once imported
const handlers = {hello: [onHello], reply: [onReply], error: [onError]};   // frame type -> handlers
const replyHandlers = {};                                                  // request type -> handler
const quietFailures = new Set();
let inbox = Promise.resolve();   // frames are handled one after the other, each after the panels it needs loaded

/** Imports the panels `names` this page does not have yet (all at once), then sets each up in order. */
async function loadPanels(names) {
  const wanted = names.filter((name) => {
    if (typeof name === 'string' && PANEL_NAME.test(name)) return !panels.has(name);
    addMessage(`the server named a panel ${JSON.stringify(name)}, which is not a module name`);
    return false;
  });
  const modules = await Promise.all(wanted.map((name) => import(`./js/panels/${name}.js`).then(
    (module) => module.default,
    (err) => addMessage(`the page has no module for the server's panel "${name}" (${err.message})`))));
  wanted.forEach((name, index) => {
    const panel = modules[index];
    if (!panel || panels.has(name)) return;
    panels.set(name, panel);
    for (const [type, handler] of Object.entries(panel.frames || {})) (handlers[type] = handlers[type] || []).push(handler);
    Object.assign(replyHandlers, panel.replies || {});
    for (const type of panel.quietFailures || []) quietFailures.add(type);
    if (panel.setup) panel.setup();
  });
}

/* ============================================================ connection */

function socketUrl() {
  const token = new URLSearchParams(location.search).get('token');
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/ws` + (token === null ? '' : `?token=${encodeURIComponent(token)}`);
}

function connect() {
  const socket = new WebSocket(socketUrl());
  app.socket = socket;
  // The page counts as connected from the server's hello on, once the panels it names are set up.
  socket.addEventListener('message', (event) => {
    inbox = inbox.then(() => handleFrameText(event.data, socket))
      .catch((err) => addMessage(`could not handle a frame: ${err.message}`));
  });
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
  const status = $('status');
  labView.connected = on;
  status.textContent = on ? 'connected' : 'disconnected';
  status.classList.toggle('on', on);
  status.classList.toggle('off', !on);
}

async function handleFrameText(text, socket) {
  if (app.socket !== socket) return;   // a frame of a socket that closed while the panels loaded
  let frame;
  try {
    frame = JSON.parse(text);
  } catch (err) {
    addMessage('the server sent a frame that is not JSON');
    return;
  }
  if (frame && frame.type === 'hello') await loadPanels(Array.isArray(frame.panels) ? frame.panels : []);
  // Unknown types are ignored, so a newer server does not break the page.
  for (const handler of (frame && handlers[frame.type]) || []) {
    try {
      handler(frame);
    } catch (err) {
      addMessage(`could not show a "${frame.type}" frame: ${err.message}`);
    }
  }
}

/* ============================================================ frames every panel shares */

function onHello(frame) {
  if (frame.version !== 1) addMessage(`server protocol version ${frame.version}, this page knows version 1`);
  // A new session (maybe a restarted server running other simulators): forget what the old one showed.
  for (const panel of panels.values()) if (panel.onHello) panel.onHello(frame);
  updatePanels();
  setConnected(true);
  // The server keeps no per-page memory across reconnects: the panels ask again for what they showed.
  for (const panel of panels.values()) if (panel.restore) panel.restore();
}

function onReply(frame) {
  const reply = {id: frame.id, ok: frame.ok === true, text: String(frame.text)};
  labView.replies.push(reply);
  const context = app.pending.get(reply.id);
  app.pending.delete(reply.id);
  if (!reply.ok && !(context && quietFailures.has(context.type))) addMessage(reply.text);
  const handler = context && replyHandlers[context.type];
  if (handler) handler(reply, context);
}

function onError(frame) {
  const text = String(frame.text);
  labView.errors.push(text);
  addMessage(text);
}

/* ============================================================ start */

connect();
