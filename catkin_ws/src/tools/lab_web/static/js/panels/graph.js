/*
 * The graph panel: the master's topics (with rates), nodes and services from `graph` frames; a click on a topic
 * echoes its latest message (`echo` command and frames).
 */
import {$, app, element, isNumber, send, setText} from '../core.js';

function byName(a, b) {
  return a.name < b.name ? -1 : a.name > b.name ? 1 : 0;
}

function onGraph(frame) {
  const nodes = (frame.nodes || []).slice().sort();
  const topics = (frame.topics || []).slice().sort(byName);
  const services = (frame.services || []).slice().sort(byName);
  renderNameList($('graph-nodes'), nodes.map((name) => [name, '']));
  renderNameList($('graph-services'), services.map((s) => [s.name, s.node || '']));
  renderTopics(topics);
  setText($('node-count'), `(${nodes.length})`);
  setText($('topic-count'), `(${topics.length})`);
  setText($('service-count'), `(${services.length})`);
}

function onEcho(frame) {
  if (frame.topic !== app.selectedTopic) return;
  $('echo').textContent = frame.text;
}

/** Rebuilds a name list only when its content changed (the graph repeats every 2 s). */
function renderNameList(list, entries) {
  const key = JSON.stringify(entries);
  if (list.dataset.key === key) return;
  list.dataset.key = key;
  list.replaceChildren(...entries.map(([name, note]) => {
    const item = document.createElement('li');
    item.textContent = name;
    if (note) item.appendChild(element('span', 'subtle', note));
    return item;
  }));
}

/** Updates topic rows in place (not rebuilt), so a click that lands during an update still counts. */
function renderTopics(topics) {
  const table = $('graph-topics');
  const rows = new Map(Array.from(table.rows, (row) => [row.dataset.topic, row]));
  topics.forEach((topic, index) => {
    let row = rows.get(topic.name);
    rows.delete(topic.name);
    if (!row) row = createTopicRow(topic.name);
    setText(row.cells[1], topic.type || '');
    setText(row.cells[2], isNumber(topic.hz) ? `${topic.hz.toFixed(1)} Hz` : '—');
    setText(row.cells[3], (topic.publishers || []).join(', '));
    row.title = `subscribers: ${(topic.subscribers || []).join(', ') || 'none'}`;
    row.classList.toggle('selected', topic.name === app.selectedTopic);
    if (table.rows[index] !== row) table.insertBefore(row, table.rows[index] || null);
  });
  for (const stale of rows.values()) stale.remove();
}

function createTopicRow(name) {
  const row = document.createElement('tr');
  row.dataset.topic = name;
  row.tabIndex = 0;
  row.append(element('td', '', name), element('td', 'type', ''), element('td', 'num', ''), element('td', '', ''));
  return row;
}

function toggleTopic(name) {
  app.selectedTopic = app.selectedTopic === name ? null : name;
  for (const row of $('graph-topics').rows) row.classList.toggle('selected', row.dataset.topic === app.selectedTopic);
  const echo = $('echo');
  echo.textContent = '';
  echo.classList.toggle('waiting', Boolean(app.selectedTopic));
  setText($('echo-topic'), app.selectedTopic || '');
  send({type: 'echo', topic: app.selectedTopic});
}

function setup() {
  const table = $('graph-topics');
  table.addEventListener('click', (event) => {
    const row = event.target.closest('tr[data-topic]');
    if (row) toggleTopic(row.dataset.topic);
  });
  table.addEventListener('keydown', (event) => {
    const row = event.target.closest('tr[data-topic]');
    if (row && (event.key === 'Enter' || event.key === ' ')) {
      event.preventDefault();
      toggleTopic(row.dataset.topic);
    }
  });
}

/** The server keeps no per-page memory across reconnects: ask again. */
function restore() {
  if (app.selectedTopic) send({type: 'echo', topic: app.selectedTopic});
}

export default {name: 'graph', setup, restore, frames: {graph: onGraph, echo: onEcho}};
