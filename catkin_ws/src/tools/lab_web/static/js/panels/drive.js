/*
 * The drive panel: the arrow keys and the drive buttons send `teleop` at ~10 Hz while held and zeros once on
 * release, to the robot when there is one, else to turtle1.
 */
import {$, addVisibility, app, isNumber, isPageKey, isTypingTarget, send, setText} from '../core.js';

const TELEOP_PERIOD_MS = 100;
const SPEED_FRACTION = 0.8;           // drive at 80 % of the server's limits, so never beyond them
const KEY_DIRECTIONS = {ArrowUp: 'forward', ArrowDown: 'back', ArrowLeft: 'left', ArrowRight: 'right'};
const held = {keys: new Set(), buttons: new Set()};
let timer = null;
let moving = false;                    // a non-stop command went out since the last zeros

function teleopTarget() {
  if (app.robotSeen) return 'robot';
  if (app.turtlesim) return 'turtle1';
  return null;
}

/** [linear m/s, angular rad/s] for a target; hello names turtlesim's limits "turtle", commands say "turtle1". */
function limitsFor(target) {
  const limits = app.limits[target] || (target === 'turtle1' ? app.limits.turtle : null);
  if (!Array.isArray(limits) || limits.length < 2 || !isNumber(limits[0]) || !isNumber(limits[1])) return null;
  return [Math.abs(limits[0]), Math.abs(limits[1])];
}

function heldDirections() {
  return new Set([...held.keys, ...held.buttons]);
}

function sendTeleop(linear, angular) {
  const target = teleopTarget();
  const limits = limitsFor(target);
  if (!target || !limits) return;
  const clamp = (value, limit) => Math.max(-limit, Math.min(limit, value));
  send({type: 'teleop', target, linear: clamp(linear * limits[0], limits[0]), angular: clamp(angular * limits[1], limits[1])});
}

/** The held keys and buttons as a command in units of the limits (each within +-SPEED_FRACTION). */
function sendHeldCommand() {
  const directions = heldDirections();
  const linear = (directions.has('forward') ? 1 : 0) - (directions.has('back') ? 1 : 0);
  const angular = (directions.has('left') ? 1 : 0) - (directions.has('right') ? 1 : 0);
  sendTeleop(SPEED_FRACTION * linear, SPEED_FRACTION * angular);
  moving = true;
}

function sendZeros() {
  sendTeleop(0, 0);
  moving = false;
}

/** Called whenever the set of held keys/buttons changes: send now, then every 100 ms, zeros once at the end. */
function teleopChanged() {
  clearInterval(timer);
  timer = null;
  for (const button of document.querySelectorAll('.drive-btn[data-drive]')) {
    button.classList.toggle('held', heldDirections().has(button.dataset.drive));
  }
  if (heldDirections().size) {
    sendHeldCommand();
    timer = setInterval(sendHeldCommand, TELEOP_PERIOD_MS);
  } else if (moving) {
    sendZeros();
  }
}

/** Page hidden, window unfocused, unloading: nothing is held any more (keyup would never come). */
function releaseAll() {
  held.keys.clear();
  held.buttons.clear();
  teleopChanged();
}

function updateTeleopInfo() {
  const target = teleopTarget();
  const limits = limitsFor(target);
  setText($('teleop-target'), target || 'nothing to drive yet');
  setText($('teleop-speeds'), limits
    ? `${(SPEED_FRACTION * limits[0]).toFixed(2)} m/s, ${(SPEED_FRACTION * limits[1]).toFixed(2)} rad/s` : '');
  return false;                         // drives whatever shows; not a view of its own
}

function setup() {
  addVisibility(updateTeleopInfo);
  window.addEventListener('keydown', (event) => {
    const direction = KEY_DIRECTIONS[event.key];
    if (!direction || !isPageKey(event)) return;
    event.preventDefault();             // arrows drive; they must not scroll the page
    if (!held.keys.has(direction)) {
      held.keys.add(direction);
      teleopChanged();
    }
  });
  window.addEventListener('keyup', (event) => {
    const direction = KEY_DIRECTIONS[event.key];
    if (!direction) return;
    if (!isTypingTarget(event.target)) event.preventDefault();
    if (held.keys.delete(direction)) teleopChanged();
  });
  for (const button of document.querySelectorAll('.drive-btn[data-drive]')) {
    const direction = button.dataset.drive;
    const release = () => {
      if (held.buttons.delete(direction)) teleopChanged();
    };
    button.addEventListener('pointerdown', (event) => {
      if (event.button !== 0) return;
      event.preventDefault();
      held.buttons.add(direction);
      teleopChanged();
    });
    button.addEventListener('pointerup', release);
    button.addEventListener('pointerleave', release);
    button.addEventListener('pointercancel', release);
    button.addEventListener('contextmenu', (event) => event.preventDefault());  // touch long-press
  }
  $('drive-stop').addEventListener('click', () => {
    held.keys.clear();
    held.buttons.clear();
    teleopChanged();
    sendZeros();                          // explicit stop: always send, even when nothing was held
  });
  window.addEventListener('blur', releaseAll);
  window.addEventListener('beforeunload', releaseAll);
  window.addEventListener('pagehide', releaseAll);
  document.addEventListener('visibilitychange', () => {
    if (document.hidden) releaseAll();
  });
}

function onHello(frame) {
  app.limits = frame.teleop_limits || {};
}

export default {name: 'drive', setup, onHello};
