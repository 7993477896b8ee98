/*
 * The turtlesim panel: turtlesim's window on its own canvas (#turtlesim): the background, the pen trails from
 * turtlesim's ~canvas image (`canvas` frames) and the turtles (`turtlesim` frames).
 */
import {$, addRenderer, addVisibility, app, decodePng, isNumber, labView, recordLatency, requestRender,
  updatePanels} from '../core.js';

const TURTLE_PX = 500;                  // turtlesim's pen canvas is 500 x 500 pixels
const DEFAULT_TURTLE_SIZE_M = 500 / 45; // turtlesim draws 45 px per metre: 11.08 m
const COLORS = {turtle: '#2f9e44', turtleEdge: '#1b5e20'};
const canvas = $('turtlesim');
const ctx = canvas.getContext('2d', {willReadFrequently: true});

function onTurtlesim(frame) {
  const first = !app.turtlesim;
  app.turtlesim = frame;
  recordLatency(frame.stamp_ms);
  if (!app.robotSeen) app.stateTimes.push(performance.now());   // #fps counts turtlesim frames without a robot
  $('turtlesim-hint').hidden = frame.canvas !== false;
  if (first) updatePanels();
  requestRender('turtle');
}

/** Decodes each pen canvas PNG once; frames are drawn from the decoded image. */
function onCanvas(frame) {
  decodePng('turtlesim canvas', frame.png, (image) => {
    app.turtleImage = image;
    requestRender('turtle');
  });
}

export function turtleToPixel(x, y) {
  const size = (app.turtlesim && isNumber(app.turtlesim.size_m) && app.turtlesim.size_m > 0)
    ? app.turtlesim.size_m : DEFAULT_TURTLE_SIZE_M;
  return [x * TURTLE_PX / size, TURTLE_PX - y * TURTLE_PX / size];
}

function drawTurtlesim() {
  const ts = app.turtlesim;
  const bg = Array.isArray(ts.background) ? ts.background : [69, 86, 255];
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = `rgb(${bg[0]}, ${bg[1]}, ${bg[2]})`;
  ctx.fillRect(0, 0, TURTLE_PX, TURTLE_PX);
  // Without ~publish_canvas the last image would be stale (turtlesim restarted): draw only live ones.
  if (app.turtleImage && ts.canvas !== false) ctx.drawImage(app.turtleImage, 0, 0, TURTLE_PX, TURTLE_PX);
  for (const turtle of ts.turtles || []) drawTurtle(turtle);
}

/** A small turtle seen from above: shell, head in front (along theta), four legs. */
function drawTurtle(turtle) {
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

function updateVisibility() {
  $('turtlesim-panel').hidden = !app.turtlesim;
  return Boolean(app.turtlesim);
}

function setup() {
  labView.turtleToPixel = turtleToPixel;
  addRenderer('turtle', drawTurtlesim, () => Boolean(app.turtlesim));
  addVisibility(updateVisibility);
}

function onHello() {
  app.turtlesim = null;
  app.turtleImage = null;
}

export default {name: 'turtlesim', setup, onHello, frames: {turtlesim: onTurtlesim, canvas: onCanvas}};
