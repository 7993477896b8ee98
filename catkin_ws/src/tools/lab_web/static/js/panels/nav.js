/*
 * The navigation panel: amcl's and move_base's displays as RViz's turtlebot3_navigation view draws them: the
 * global and local costmaps (RViz's costmap colours at its Map display's alpha 0.7), the global plan (green) and
 * local plan (yellow), the particle cloud as arrows (RViz's PoseArray: red-orange, 0.3 m), amcl's pose with its
 * position covariance as an ellipse of one standard deviation, and move_base's current goal (magenta arrow).
 * explore_lite's frontiers as its markers say (points of each frontier's cells, a sphere at each, in their colours).
 * Each item is drawn in its own frame: the fixed frame as it is, the picked robot's odom through map -> odom; others
 * not at all.
 */
import {ArrowCloud} from '../arrow_cloud.js';
import {addMessage, app, decodeFloat32, decodePng, isNumber, labView} from '../core.js';
import {addLayer, currentView, drawGridImage, redraw, tracePath, worldToPixel} from '../view.js';

const COSTMAP_ALPHA = 0.7;
const PARTICLE_RGB = [255, 25, 0];
const COLORS = {global: '#00b000', local: '#e0c000', particle: `rgb(${PARTICLE_RGB.join(', ')})`, amcl: '#4060ff',
  goal: '#ff00ff'};
const PARTICLE_LENGTH_M = 0.3;
const particleCloud = new ArrowCloud(PARTICLE_RGB, (ctx, tail, yaw, lengthPx) => arrow(ctx, [0, 0, yaw], lengthPx,
  COLORS.particle, 2, tail));
const costmaps = {};            // name -> {image, frame}
let nav = null;                 // the items of every nav frame so far, particles' poses as a Float32Array

function onCostmap(frame) {
  if (frame.error) {
    addMessage(`${frame.name} costmap: ${frame.error}`);
    return;
  }
  decodePng(`${frame.name} costmap`, frame.png, (image) => {
    costmaps[frame.name] = {image, frame};
    labView.costmaps += 1;
    redraw('costmaps');
  });
}

/** The particles' x, y, yaw per pose as one Float32Array (null if it does not add up to `count` poses). */
function decodePoses(particles) {
  const poses = decodeFloat32(particles.poses);
  return poses && poses.length === particles.count * 3 ? poses : null;
}

/** A nav frame brings only the items that changed: the others stay as the earlier frames left them. */
function onNav(frame) {
  const {plans, particles, ...rest} = frame;
  delete rest.type;
  nav = Object.assign(nav || {plans: {}, particles: null, amcl: null, goal: null, frontiers: []}, rest);
  if (plans) Object.assign(nav.plans, plans);
  if (particles) {
    const poses = decodePoses(particles);
    if (poses) nav.particles = {frame: particles.frame, poses};
    else addMessage('particle cloud: its poses do not add up to its count');
  }
  labView.nav = nav;
  if (particles) redraw('particles');
  redraw('vectors');      // cheap without the particles (and it draws them where they are in odom)
}

function fixedFrame() {
  return (app.fixed && app.fixed.frame) || 'odom';
}

/** The picked robot's odom frame ("odom", or "tb3_0/odom" with its tf_prefix). */
function odomFrame() {
  return (app.fixed && app.fixed.odom_frame) || 'odom';
}

/** Whether an item in `frame` belongs to the layer drawing `layerFrame` ('fixed' or 'odom'). */
function inLayer(frame, layerFrame) {
  if (frame === fixedFrame()) return layerFrame === 'fixed';
  return frame === odomFrame() && layerFrame === 'odom';
}

/** An arrow as one path (shaft and both sides of its head) stroked once: a third of the strokes of three lines.
 *  Its tail is where the view puts `pose`, or at canvas pixel `tail` when given. */
function arrow(ctx, pose, lengthPx, color, width, tail = null) {
  const [x, y, yaw] = pose;
  const [ax, ay] = tail || worldToPixel(x, y);
  const [bx, by] = [ax + lengthPx * Math.cos(yaw), ay - lengthPx * Math.sin(yaw)];
  const head = Math.max(lengthPx * 0.3, 3);
  ctx.lineWidth = width;
  ctx.strokeStyle = color;
  ctx.beginPath();
  ctx.moveTo(ax, ay);
  ctx.lineTo(bx, by);
  for (const side of [-1, 1]) {
    const back = yaw + Math.PI - side * 0.5;
    ctx.moveTo(bx, by);
    ctx.lineTo(bx + head * Math.cos(back), by - head * Math.sin(back));
  }
  ctx.stroke();
}

/** One standard deviation of the position: the ellipse's axes are the square roots of the covariance's
 *  eigenvalues, along its eigenvectors. */
export function covarianceEllipse(xx, xy, yy) {
  const mean = (xx + yy) / 2;
  const spread = Math.sqrt(((xx - yy) / 2) ** 2 + xy ** 2);
  return {major: Math.sqrt(Math.max(mean + spread, 0)), minor: Math.sqrt(Math.max(mean - spread, 0)),
    angle: 0.5 * Math.atan2(2 * xy, xx - yy)};
}

function drawAmcl(ctx, amcl) {
  const [x, y, yaw] = amcl.pose;
  const [xx, xy, yy] = amcl.covariance;
  const {major, minor, angle} = covarianceEllipse(xx, xy, yy);
  const scale = currentView().scale;
  const [px, py] = worldToPixel(x, y);
  ctx.save();
  ctx.globalAlpha = 0.5;
  ctx.fillStyle = COLORS.amcl;
  ctx.beginPath();
  ctx.ellipse(px, py, Math.max(major * scale, 1), Math.max(minor * scale, 1), -angle, 0, 2 * Math.PI);
  ctx.fill();
  ctx.restore();
  arrow(ctx, [x, y, yaw], 0.4 * scale, COLORS.amcl, 3);
}

function drawCostmaps(ctx, layerFrame) {
  for (const name of ['global', 'local']) {
    const costmap = costmaps[name];
    if (costmap && inLayer(costmap.frame.frame, layerFrame)) drawGridImage(ctx, costmap.image, costmap.frame, COSTMAP_ALPHA);
  }
}

/** amcl's cloud, an arrow per particle (js/arrow_cloud.js: one picture, not thousands of paths). */
function drawParticles(ctx, layerFrame) {
  if (!nav || !nav.particles || !inLayer(nav.particles.frame, layerFrame)) return;
  particleCloud.draw(ctx, nav.particles.poses, PARTICLE_LENGTH_M * currentView().scale, worldToPixel);
}

/** The plans, amcl's pose, the goal and the frontiers: above both costmaps and the particles. */
function drawVectors(ctx, layerFrame) {
  if (!nav) return;
  for (const name of ['global', 'local']) {
    const plan = (nav.plans || {})[name];
    if (!plan || !inLayer(plan.frame, layerFrame) || plan.points.length < 2) continue;
    tracePath(ctx, plan.points);
    ctx.lineWidth = 3;
    ctx.lineJoin = 'round';
    ctx.strokeStyle = COLORS[name];
    ctx.stroke();
  }
  const scale = currentView().scale;
  if (nav.amcl && inLayer(nav.amcl.frame, layerFrame) && nav.amcl.covariance.every(isNumber)) drawAmcl(ctx, nav.amcl);
  if (nav.goal && inLayer(nav.goal.frame, layerFrame)) arrow(ctx, nav.goal.pose, 0.5 * scale, COLORS.goal, 4);
  for (const marker of nav.frontiers || []) {
    if (inLayer(marker.frame, layerFrame)) drawMarker(ctx, marker, scale);
  }
}

function drawMarker(ctx, marker, scale) {
  const [r, g, b, a] = marker.rgba.map((value) => (isNumber(value) ? value : 1));
  ctx.fillStyle = `rgba(${Math.round(r * 255)}, ${Math.round(g * 255)}, ${Math.round(b * 255)}, ${a})`;
  const size = Math.max(marker.scale * scale, 2);
  for (const [x, y] of marker.points) {
    const [px, py] = worldToPixel(x, y);
    if (marker.kind === 'points') {
      ctx.fillRect(px - size / 2, py - size / 2, size, size);
    } else {
      ctx.beginPath();
      ctx.arc(px, py, size / 2, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
}

function setup() {
  labView.costmaps = 0;
  labView.covarianceEllipse = covarianceEllipse;
  addLayer(16, (ctx) => drawCostmaps(ctx, 'fixed'), 'fixed');    // with the map: they change as often
  addLayer(17, (ctx) => drawCostmaps(ctx, 'odom'), 'odom');
  addLayer(18, (ctx) => drawParticles(ctx, 'fixed'), 'fixed');   // a plane of their own: amcl moves odom often
  addLayer(19, (ctx) => drawVectors(ctx, 'fixed'), 'fixed');
  addLayer(19.5, (ctx) => {
    drawParticles(ctx, 'odom');
    drawVectors(ctx, 'odom');
  }, 'odom');
}

function onHello() {
  nav = null;
  labView.nav = null;
  for (const name of Object.keys(costmaps)) delete costmaps[name];
  redraw();
}

export default {name: 'nav', setup, onHello, frames: {costmap: onCostmap, nav: onNav}};
