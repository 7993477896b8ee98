/*
 * The service panel (the Week 4 form): pick a service (the Week 4 ones, then any other the graph lists), fill
 * in its request's fields (read from its type with `service_fields`) and `call_service`.
 */
import {$, element, request} from '../core.js';

const INT_TYPE = /^(u?int(8|16|32|64)|byte|char)$/;
const FLOAT_TYPE = /^float(32|64)$/;
const form = {
  loadedFor: null,           // service whose request fields are shown
  retry: null,               // service whose fields failed while it was not running: retry once it appears
  listed: new Set(),         // service names in the latest graph frame
  graphSeen: false,          // a graph frame came: `listed` is what runs
};

function addServiceOptions(services) {
  const select = $('service-name');
  const known = new Set(Array.from(select.options, (option) => option.value));
  let group = select.querySelector('optgroup');
  for (const {name} of services) {
    if (typeof name !== 'string' || known.has(name)) continue;
    if (name.startsWith('/gazebo/') || name.includes('/get_loggers') || name.includes('/set_logger_level')) continue;
    if (!group) {
      group = document.createElement('optgroup');
      group.label = 'Other services';
      select.appendChild(group);
    }
    const option = element('option', '', name);
    option.value = name;
    group.appendChild(option);
    known.add(name);
  }
}

/** The graph lists the services: offer them, and ask for the fields of the chosen one once it runs. */
function onGraph(frame) {
  const services = (frame.services || []).slice().sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  addServiceOptions(services);
  form.listed = new Set(services.map((s) => s.name));
  form.graphSeen = true;
  if (form.retry === $('service-name').value && form.listed.has(form.retry)) {
    form.retry = null;
    loadServiceFields();
  } else if (form.retry) {
    showWaiting(form.retry);
  }
}

/** A service that no node offers yet is not an error (turtlesim has no /move_service; a student starts the
 *  Week 4 server after opening the page): the form says what it waits for and asks once the graph lists it. */
function loadServiceFields() {
  const service = $('service-name').value;
  form.loadedFor = null;
  $('service-fields').replaceChildren();
  clearServiceReply();
  if (!form.listed.has(service)) {
    form.retry = service;
    showWaiting(service);
    return;
  }
  request('service_fields', {service}, {service});
}

function showWaiting(service) {
  $('service-reply').textContent = form.graphSeen ? `${service} is not offered by any node yet: start the node that `
    + 'offers it, or pick another service' : '';
}

function showServiceFields(reply, context) {
  const service = context.service;
  if (service !== $('service-name').value) return;     // the selection changed meanwhile
  let fields = null;
  if (reply.ok) {
    try {
      fields = JSON.parse(reply.text);
    } catch (err) {
      fields = null;
    }
  }
  const replyBox = $('service-reply');
  if (!Array.isArray(fields)) {
    // A student often starts the server after opening the page: ask again once the graph lists it.
    form.retry = form.listed.has(service) ? null : service;
    replyBox.classList.add('failed');
    replyBox.textContent = reply.text;
    return;
  }
  form.loadedFor = service;
  const box = $('service-fields');
  box.replaceChildren();
  if (!fields.length) box.appendChild(element('p', 'note', 'This service takes no request fields.'));
  for (const field of fields) box.append(...fieldInput(field));
}

/** A label and an input for one request field, the input kind chosen from its ROS type. */
function fieldInput(field) {
  const id = `field-${field.name}`;
  const label = element('label', '', field.name);
  label.htmlFor = id;
  label.appendChild(element('span', 'type', field.type));
  const input = document.createElement('input');
  input.id = id;
  input.name = field.name;
  input.dataset.type = field.type;
  if (field.type === 'bool') {
    input.type = 'checkbox';
  } else if (FLOAT_TYPE.test(field.type) || INT_TYPE.test(field.type)) {
    input.type = 'number';
    input.step = FLOAT_TYPE.test(field.type) ? 'any' : '1';
    input.value = '0';
  } else {
    input.type = 'text';
    input.maxLength = 256;
  }
  return [label, input];
}

/** The form's values as JSON: bool -> true/false, numbers -> Number, strings as typed; null if one is bad. */
function collectFields() {
  const fields = {};
  for (const input of $('service-fields').querySelectorAll('input[name]')) {
    const type = input.dataset.type;
    if (type === 'bool') {
      fields[input.name] = input.checked;
    } else if (input.type === 'number') {
      const value = input.value.trim() === '' ? 0 : Number(input.value);
      if (input.validity.badInput || !Number.isFinite(value)) {
        showServiceReply({ok: false, text: `${input.name} must be a number`});
        return null;
      }
      fields[input.name] = value;
    } else {
      fields[input.name] = input.value;
    }
  }
  return fields;
}

function callService() {
  const fields = collectFields();
  if (!fields) return;
  const service = $('service-name').value;
  clearServiceReply();
  if (request('call_service', {service, fields}, {service}) !== null) $('service-reply').classList.add('pending');
}

function clearServiceReply() {
  const replyBox = $('service-reply');
  replyBox.textContent = '';
  replyBox.classList.remove('failed', 'pending');
}

function showServiceReply(reply) {
  const replyBox = $('service-reply');
  replyBox.classList.remove('pending');
  replyBox.classList.toggle('failed', !reply.ok);
  replyBox.textContent = reply.ok ? reply.text : `error: ${reply.text}`;
}

function setup() {
  $('service-name').addEventListener('change', loadServiceFields);
  $('service-form').addEventListener('submit', (event) => {
    event.preventDefault();
    callService();
  });
}

/** The server keeps no per-page memory across reconnects: ask again. */
function restore() {
  if (form.loadedFor !== $('service-name').value) loadServiceFields();
}

export default {
  name: 'services',
  setup,
  restore,
  frames: {graph: onGraph},
  replies: {service_fields: showServiceFields, call_service: showServiceReply},
  // A form asking for a service that is not running yet says so in its own reply box, not as an error.
  quietFailures: ['service_fields'],
};
