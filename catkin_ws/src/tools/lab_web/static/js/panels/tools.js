/*
 * The tools panel: RViz's publishing tools on the top view. Pick "2D Pose Estimate" or "2D Nav Goal", then press
 * where the robot is (or should go) and drag towards where it faces; "Publish Point" takes a click. As in RViz,
 * a tool is used once and the view goes back to its default tool (here: moving boxes). "Cancel goal" cancels
 * every move_base goal. Everything is published in the fixed frame (map once there is a map). A tool shows only
 * while some node subscribes to its topic (amcl to /initialpose, move_base to its goal and cancel topics), so the
 * Week 4 arena or turtlesim offers nothing that would go nowhere.
 */
import {$, app, element, isPageKey, send} from '../core.js';
import {addLayer, canvas, canvasPoint, currentView, pixelToWorld, redraw, strokeLine, worldToPixel} from '../view.js';

const TOOLS = [
  {kind: 'initial_pose', label: '2D Pose Estimate', topic: '/initialpose', color: '#2fa84f',
    title: 'Drag from where the robot is towards where it faces: /initialpose'},
  {kind: 'nav_goal', label: '2D Nav Goal', topic: '/move_base_simple/goal', color: '#c02fc0',
    title: 'Drag from the goal towards where the robot should face: /move_base_simple/goal'},
  {kind: 'publish_point', label: 'Publish Point', topic: '/clicked_point', color: '#d08000',
    title: 'Click a point: /clicked_point'},
];
const CANCEL_TOPIC = '/move_base/cancel';
const MIN_DRAG_PX = 4;                  // a shorter drag keeps the robot's heading along +x
const round3 = (value) => Math.round(value * 1000) / 1000;
const buttons = new Map();              // tool kind -> button
let cancelButton = null;
let drag = null;                        // {tool, start: [x, y] fixed frame, end}

function choose(kind) {
  app.tool = app.tool === kind ? null : kind;
  for (const [name, button] of buttons) button.classList.toggle('active', name === app.tool);
  canvas.style.cursor = app.tool ? 'crosshair' : '';
}

function fixedFrame() {
  return (app.fixed && app.fixed.frame) || 'odom';
}

/** The drag's heading in the fixed frame (y up), 0 when it was too short to mean one. */
function dragYaw(d) {
  const [ax, ay] = worldToPixel(...d.start);
  const [bx, by] = worldToPixel(...d.end);
  return Math.hypot(bx - ax, by - ay) < MIN_DRAG_PX ? 0 : Math.atan2(d.end[1] - d.start[1], d.end[0] - d.start[0]);
}

function publish(d) {
  const [x, y] = d.start.map(round3);
  const frame = fixedFrame();
  if (d.tool.kind === 'publish_point') send({type: 'publish_point', frame, x, y});
  else send({type: d.tool.kind, frame, x, y, yaw: dragYaw(d)});
}

/** The arrow RViz draws while a pose tool is dragged. */
function drawDrag(ctx) {
  if (!drag) return;
  const [ax, ay] = worldToPixel(...drag.start);
  ctx.fillStyle = drag.tool.color;
  ctx.beginPath();
  ctx.arc(ax, ay, 4, 0, 2 * Math.PI);
  ctx.fill();
  if (drag.tool.kind === 'publish_point') return;
  const yaw = dragYaw(drag);
  const length = Math.max(0.5 * currentView().scale, 20);
  const [bx, by] = [ax + length * Math.cos(yaw), ay - length * Math.sin(yaw)];
  ctx.lineWidth = 3;
  strokeLine(ctx, ax, ay, bx, by, drag.tool.color);
  for (const side of [-1, 1]) {
    const back = yaw + Math.PI - side * 0.4;
    strokeLine(ctx, bx, by, bx + 10 * Math.cos(back), by - 10 * Math.sin(back), drag.tool.color);
  }
}

function setup() {
  const bar = element('div', 'tools');
  bar.id = 'tools';
  for (const tool of TOOLS) {
    const button = element('button', 'secondary tool', tool.label);
    button.type = 'button';
    button.id = `tool-${tool.kind.replace('_', '-')}`;
    button.title = tool.title;
    button.hidden = true;
    button.addEventListener('click', () => choose(tool.kind));
    buttons.set(tool.kind, button);
    bar.appendChild(button);
  }
  const cancel = element('button', 'secondary', 'Cancel goal');
  cancelButton = cancel;
  cancel.type = 'button';
  cancel.id = 'cancel-goal';
  cancel.hidden = true;
  cancel.title = 'Cancel every move_base goal (/move_base/cancel)';
  cancel.addEventListener('click', () => send({type: 'cancel_goal'}));
  bar.appendChild(cancel);
  $('world-panel').insertBefore(bar, $('world-panel').querySelector('.canvas-wrap'));
  addLayer(90, drawDrag, 'fixed');
  // Capture: a tool's press is not the box tool's.
  canvas.addEventListener('mousedown', (event) => {
    if (event.button !== 0 || !app.tool) return;
    event.preventDefault();
    event.stopImmediatePropagation();
    const at = pixelToWorld(...canvasPoint(event));
    drag = {tool: TOOLS.find((tool) => tool.kind === app.tool), start: at, end: at};
    redraw('live');
  }, true);
  window.addEventListener('mousemove', (event) => {
    if (!drag) return;
    drag.end = pixelToWorld(...canvasPoint(event));
    redraw('live');
  });
  window.addEventListener('mouseup', (event) => {
    if (!drag || event.button !== 0) return;
    drag.end = pixelToWorld(...canvasPoint(event));
    publish(drag);
    drag = null;
    choose(null);                       // one use, then back to the default tool, as RViz does
    redraw('live');
  });
  window.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && isPageKey(event) && (drag || app.tool)) {
      drag = null;
      choose(null);
      redraw('live');
    }
  });
}

/** Shows the tools whose topics some node subscribes to (the graph lists lab_web's own publishers' topics). */
function onGraph(frame) {
  const subscribed = new Set((frame.topics || []).filter((topic) => (topic.subscribers || []).length)
    .map((topic) => topic.name));
  for (const tool of TOOLS) {
    buttons.get(tool.kind).hidden = !subscribed.has(tool.topic);
    if (app.tool === tool.kind && !subscribed.has(tool.topic)) choose(null);
  }
  cancelButton.hidden = !subscribed.has(CANCEL_TOPIC);
}

export default {name: 'tools', setup, frames: {graph: onGraph}};
