/*
 * The camera panel: a thumbnail of the robot's camera while "Show camera" is ticked and the page is visible
 * (the server subscribes to the camera only while some page asks).
 */
import {$, addVisibility, app, send} from '../core.js';

function onCamera(frame) {
  if (!app.cameraOn) return;     // a frame that was on its way when the camera was switched off
  const image = $('camera-img');
  image.src = `data:image/jpeg;base64,${frame.jpeg}`;
  image.hidden = false;
  $('camera-note').hidden = true;
}

/** The camera is the robot's: no toggle without one (turtlesim has none). */
function updateVisibility() {
  $('camera-toggle').closest('.camera').hidden = !app.robotSeen;
  return false;
}

function setup() {
  addVisibility(updateVisibility);
  const toggle = $('camera-toggle');
  toggle.checked = false;       // browsers may restore a checked box on reload
  toggle.addEventListener('change', () => {
    app.cameraOn = toggle.checked;
    send({type: 'camera', on: app.cameraOn});
    $('camera-note').hidden = !app.cameraOn;
    if (!app.cameraOn) {
      $('camera-img').hidden = true;
      $('camera-img').removeAttribute('src');
    }
  });
  window.addEventListener('pagehide', () => send({type: 'camera', on: false}));
  // No thumbnails for a hidden page; ask again when it shows.
  document.addEventListener('visibilitychange', () => {
    if (app.cameraOn) send({type: 'camera', on: !document.hidden});
  });
}

/** The server keeps no per-page memory across reconnects: ask again. */
function restore() {
  if (app.cameraOn && !document.hidden) send({type: 'camera', on: true});
}

export default {name: 'camera', setup, restore, frames: {camera: onCamera}};
