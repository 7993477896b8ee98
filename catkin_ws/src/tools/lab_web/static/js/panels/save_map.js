/*
 * The save-map panel: a folder and a name, and "Save map" runs map_saver into <home>/<folder>/<name>.pgm and .yaml
 * (the reply says where). Shown only once there is a map to save.
 */
import {$, addVisibility, app, element, request} from '../core.js';

const NAME = '^[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}$';

function input(id, value, label) {
  const field = element('input');
  field.id = id;
  field.value = value;
  field.pattern = NAME;
  field.required = true;
  field.maxLength = 64;
  field.title = `${label}: letters, digits, _ . and -`;
  field.setAttribute('aria-label', label);
  return field;
}

function setup() {
  const form = element('form', 'save-map');
  form.id = 'save-map';
  form.hidden = true;
  form.autocomplete = 'off';
  const button = element('button', 'secondary', 'Save map');
  button.type = 'submit';
  button.id = 'save-map-button';
  const reply = element('span', 'subtle');
  reply.id = 'save-map-reply';
  form.append(element('span', 'subtle', '~/'), input('map-folder', 'maps', 'Folder'), element('span', 'subtle', '/'),
    input('map-name', 'my_map', 'Map name'), button, reply);
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    reply.textContent = 'saving…';
    request('save_map', {folder: $('map-folder').value, name: $('map-name').value});
  });
  $('world-panel').appendChild(form);
  addVisibility(() => {
    form.hidden = !app.mapRegion;
    return false;
  });
}

function onSaved(reply) {
  $('save-map-reply').textContent = reply.ok ? reply.text : `error: ${reply.text}`;
}

function onHello(frame) {
  $('map-folder').previousSibling.textContent = `${frame.maps_home || '~'}/`;
}

export default {name: 'save_map', setup, onHello, replies: {save_map: onSaved}};
