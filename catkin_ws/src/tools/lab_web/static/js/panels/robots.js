/*
 * The robots panel: a "Robot" picker in the top bar while more than one robot runs (multi_turtlebot3's tb3_0,
 * tb3_1, ...); picking one makes the server show and drive that robot's namespace. It builds its own markup.
 */
import {$, element, labView, send} from '../core.js';

let picker = null;

function label(namespace) {
  return namespace === '/' ? '/ (global)' : namespace;
}

function onRobots(frame) {
  const robots = Array.isArray(frame.robots) ? frame.robots.filter((name) => typeof name === 'string') : [];
  labView.robots = {robots, picked: frame.picked};
  const select = $('robot-pick');
  const shown = Array.from(select.options, (option) => option.value);
  if (shown.join('\n') !== robots.join('\n')) {
    select.replaceChildren(...robots.map((name) => {
      const option = element('option', null, label(name));
      option.value = name;
      return option;
    }));
  }
  select.value = frame.picked;
  picker.hidden = robots.length < 2;
}

function setup() {
  const select = element('select');
  select.id = 'robot-pick';
  select.addEventListener('change', () => send({type: 'pick_robot', namespace: select.value}));
  picker = element('label', 'stat robot-pick', 'Robot ');
  picker.append(select);
  picker.hidden = true;
  document.querySelector('.topbar .stats').prepend(picker);
  labView.robots = null;
}

function onHello() {
  labView.robots = null;
  picker.hidden = true;
}

export default {name: 'robots', setup, onHello, frames: {robots: onRobots}};
