/*
 * The map panel: /map as RViz's Map display draws it (unknown grey, free white, occupied black; opaque, above
 * the simulator's floor and below the robot), and the fixed frame: map once a map has come, else odom.
 */
import {addMessage, app, decodePng, isNumber, labView, updatePanels} from '../core.js';
import {addLayer, drawGridImage, redraw, updateView} from '../view.js';

let mapImage = null;            // the decoded map PNG, with the frame it came in

function onFixed(frame) {
  app.fixed = frame;
  labView.fixedFrame = frame.frame;
  updateView();
  redraw('live');   // the planes that move with odom, or draw in another frame now, are redrawn with it
}

/** Decodes each map PNG once; redraws use the decoded image. */
function onMap(frame) {
  if (frame.error) {
    addMessage(frame.error);
    return;
  }
  if (![frame.width, frame.height, frame.resolution].every(isNumber) || !Array.isArray(frame.origin)) return;
  labView.mapBytes = frame.png.length;    // the base64 PNG, as sent (benchmarks read it)
  decodePng('map', frame.png, (image) => {
    mapImage = {image, frame};
    const [x, y] = frame.origin;
    app.mapRegion = [x, y, x + frame.width * frame.resolution, y + frame.height * frame.resolution];
    labView.maps += 1;
    if (labView.maps === 1) updatePanels();   // what needs a map shows from now on
    updateView();
    redraw('grids');
  });
}

function drawMap(ctx) {
  if (mapImage) drawGridImage(ctx, mapImage.image, mapImage.frame);
}

/** Test hook: the map the page draws, as a PNG data URL of one pixel per cell (null before a map). */
function mapPng() {
  if (!mapImage) return null;
  const canvas = document.createElement('canvas');
  canvas.width = mapImage.image.width;
  canvas.height = mapImage.image.height;
  canvas.getContext('2d').drawImage(mapImage.image, 0, 0);
  return canvas.toDataURL('image/png');
}

function setup() {
  labView.maps = 0;
  labView.mapPng = mapPng;
  addLayer(15, drawMap, 'fixed');
}

function onHello(frame) {
  mapImage = null;
  app.mapRegion = null;
  app.fixed = null;
  labView.fixedFrame = typeof frame.world_frame === 'string' ? frame.world_frame : 'odom';
  redraw();
}

export default {name: 'map', setup, onHello, frames: {map: onMap, fixed: onFixed}};
