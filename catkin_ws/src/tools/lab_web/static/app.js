/*
 * app.js: the browser side of lab_web, the web view of the ROS 1 teaching lab (an ES module, no libraries).
 * One WebSocket (/ws on the page's own host) carries JSON text frames; `python3 -m lab_web.protocol` prints
 * them all. Each panel is one module under js/panels/ (set-up, frame handlers, drawing) matching one server
 * panel (lab_web/panels/); this file connects, hands each frame to the panels that handle its type, and
 * routes replies to the panel whose request it answers. Adding a panel: its module and one line in PANELS.
 */
import {$, addMessage, app, labView, updatePanels} from './js/core.js';
import camera from './js/panels/camera.js';
import drive from './js/panels/drive.js';
import graph from './js/panels/graph.js';
import map from './js/panels/map.js';
import nav from './js/panels/nav.js';
import robot from './js/panels/robot.js';
import saveMap from './js/panels/save_map.js';
import services from './js/panels/services.js';
import tools from './js/panels/tools.js';
import turtlesim from './js/panels/turtlesim.js';
import world from './js/panels/world.js';

const PANELS = [world, map, nav, robot, turtlesim, graph, camera, drive, services, tools, saveMap];
const RECONNECT_MS = 1000;

const handlers = {hello: [onHello], reply: [onReply], error: [onError]};   // frame type -> handlers
const replyHandlers = {};                                                  // request type -> handler
const quietFailures = new Set();
for (const panel of PANELS) {
  for (const [type, handler] of Object.entries(panel.frames || {})) (handlers[type] = handlers[type] || []).push(handler);
  Object.assign(replyHandlers, panel.replies || {});
  for (const type of panel.quietFailures || []) quietFailures.add(type);
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
  socket.addEventListener('open', () => {
    setConnected(true);
    for (const panel of PANELS) if (panel.restore) panel.restore();
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
  const status = $('status');
  labView.connected = on;
  status.textContent = on ? 'connected' : 'disconnected';
  status.classList.toggle('on', on);
  status.classList.toggle('off', !on);
}

function handleFrameText(text) {
  let frame;
  try {
    frame = JSON.parse(text);
  } catch (err) {
    addMessage('the server sent a frame that is not JSON');
    return;
  }
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
  for (const panel of PANELS) if (panel.onHello) panel.onHello(frame);
  updatePanels();
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

for (const panel of PANELS) if (panel.setup) panel.setup();
connect();
