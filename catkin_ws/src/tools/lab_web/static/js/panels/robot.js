/*
 * The robot panel: the driven robot from `state` frames (its pose from /odom, its trail, the newest LiDAR sweep)
 * on the world canvas, and the sim time, real-time factor and state rate in the top bar.
 */
import {$, app, decodeFloat32, isNumber, labView, recordLatency, setText, updatePanels, validRobot} from '../core.js';
import {COLORS, ROBOT_RADIUS_M, addLayer, currentView, redraw, strokeLine, tracePath, updateView, worldToPixel}
  from '../view.js';

const TRAIL_MAX_POINTS = 3000;
const STATS_PERIOD_MS = 250;

/** The server sends the trail incrementally: reset replaces the page's copy, otherwise points are appended. */
function updateTrail(update) {
  if (!update || !Array.isArray(update.points)) return;
  app.trail = update.reset ? update.points.slice() : app.trail.concat(update.points);
  if (app.trail.length > TRAIL_MAX_POINTS) app.trail = app.trail.slice(app.trail.length - TRAIL_MAX_POINTS);
}

let scanPoints = [];            // the newest sweep's hits as [[x, y], ...]: a state frame brings a sweep only once

/** The sweep's hits as [[x, y], ...]. */
function scanHits(base64) {
  const values = decodeFloat32(base64) || [];
  const points = [];
  for (let i = 0; i + 1 < values.length; i += 2) points.push([values[i], values[i + 1]]);
  return points;
}

function onState(frame) {
  if (typeof frame.scan === 'string') scanPoints = scanHits(frame.scan);
  frame.scan = scanPoints;
  app.state = frame;
  updateTrail(frame.trail);
  labView.frames += 1;
  labView.robot = frame.robot || null;
  recordLatency(frame.stamp_ms);
  app.stateTimes.push(performance.now());
  if (frame.robot && !app.robotSeen) {
    app.robotSeen = true;
    updatePanels();
  }
  updateView();
  redraw('live');
}

/** The top bar's sim time, real-time factor and state frames per second (counted over the last second), every
 *  STATS_PERIOD_MS rather than with each state frame: a changed text lays the page out again, 1.5-2 ms of the main
 *  thread's 10-15 ms per frame (DevTools trace) with navigation shown, and the real-time factor's last digit changed
 *  with nearly every frame. */
function updateStats() {
  const now = performance.now();
  while (app.stateTimes.length && now - app.stateTimes[0] > 1000) app.stateTimes.shift();
  setText($('fps'), String(app.stateTimes.length));
  const state = app.state || {};
  setText($('sim-time'), isNumber(state.sim_time) ? state.sim_time.toFixed(1) : '—');
  setText($('rtf'), isNumber(state.rtf) ? `${state.rtf.toFixed(2)}x` : '—');
}

function drawTrail(ctx) {
  if (app.trail.length < 2) return;
  tracePath(ctx, app.trail);
  ctx.lineWidth = 2;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = COLORS.trail;
  ctx.stroke();
}

/** 2 x 2 px dots on whole pixels, covering both the rounded and the truncated pixel of each hit. */
function drawScan(ctx) {
  ctx.fillStyle = COLORS.scan;
  for (const hit of (app.state || {}).scan || []) {
    const [px, py] = worldToPixel(hit[0], hit[1]);
    ctx.fillRect(Math.round(px) - 1, Math.round(py) - 1, 2, 2);
  }
}

function drawRobot(ctx) {
  const robot = validRobot((app.state || {}).robot);
  if (!robot) return;
  const [px, py] = worldToPixel(robot.x, robot.y);
  const r = Math.max(ROBOT_RADIUS_M * currentView().scale, 4);
  ctx.beginPath();
  ctx.arc(px, py, r, 0, 2 * Math.PI);
  ctx.fillStyle = COLORS.robot;
  ctx.fill();
  ctx.lineWidth = 2;
  ctx.lineCap = 'butt';
  strokeLine(ctx, px, py, px + r * Math.cos(robot.yaw || 0), py - r * Math.sin(robot.yaw || 0), COLORS.heading);
}

function setup() {
  addLayer(40, drawTrail);
  addLayer(50, drawScan);
  addLayer(100, drawRobot);     // last: always on top
  setInterval(updateStats, STATS_PERIOD_MS);
}

function onHello() {
  app.state = null;
  app.trail = [];
  scanPoints = [];
  app.robotSeen = false;
  labView.robot = null;
}

export default {name: 'robot', setup, onHello, frames: {state: onState}};
