/*
 * The map panel: /map as RViz's Map display draws it (unknown grey, free white, occupied black; opaque, above
 * the simulator's floor and below the robot), and the fixed frame: map once a map has come, else odom.
 */
import {addMessage, app, isNumber, labView, requestRender} from '../core.js';
import {addLayer, currentView, updateView, worldToPixel} from '../view.js';

let mapImage = null;            // the decoded map PNG, with the frame it came in
let mapSeq = 0;

function onFixed(frame) {
  app.fixed = frame;
  labView.fixedFrame = frame.frame;
  updateView();
  requestRender('world');
}

/** Decodes each map PNG once; redraws use the decoded image. */
function onMap(frame) {
  if (frame.error) {
    addMessage(frame.error);
    return;
  }
  if (![frame.width, frame.height, frame.resolution].every(isNumber) || !Array.isArray(frame.origin)) return;
  const seq = ++mapSeq;
  const image = new Image();
  image.onload = () => {
    if (seq !== mapSeq) return;       // a newer map arrived while this one decoded
    mapImage = {image, frame};
    const [x, y] = frame.origin;
    app.mapRegion = [x, y, x + frame.width * frame.resolution, y + frame.height * frame.resolution];
    labView.maps += 1;
    updateView();
    requestRender('world');
  };
  image.onerror = () => addMessage('could not decode the map image');
  image.src = `data:image/png;base64,${frame.png}`;
}

/** A pixel per cell, row 0 at the origin's y and upwards: the image is flipped and turned by the origin's yaw. */
function drawMap(ctx) {
  if (!mapImage) return;
  const {image, frame} = mapImage;
  const [x, y, yaw] = frame.origin;
  const [px, py] = worldToPixel(x, y);
  const scale = frame.resolution * currentView().scale;
  ctx.translate(px, py);
  ctx.rotate(-(yaw || 0));
  ctx.scale(scale, -scale);
  ctx.imageSmoothingEnabled = false;  // cells stay sharp squares, as RViz draws them
  ctx.drawImage(image, 0, 0);
}

function setup() {
  labView.maps = 0;
  addLayer(15, drawMap, 'fixed');
}

function onHello() {
  mapImage = null;
  app.mapRegion = null;
  app.fixed = null;
  labView.fixedFrame = 'odom';
}

export default {name: 'map', setup, onHello, frames: {map: onMap, fixed: onFixed}};
