// Share and export (issue 8): a link that reproduces this set-up (the scenario, where the
// robot starts and goes, the map edits since the scenario was loaded and every parameter
// changed; `share_token`), the telemetry as CSV (`telemetry_csv`) and the frame on the
// canvas as PNG.
import { el } from '../dom.js';
import { download, downloadText } from '../download.js';

export function createShare(root, canvas, app) {
  const { demo } = app;

  const link = el('input', {
    type: 'text', id: 'share-link', class: 'share-link', readonly: true, hidden: true,
    'aria-label': 'Share link', title: 'The link to this set-up: open it to get the same scenario, edits and parameters',
  });
  link.addEventListener('focus', () => link.select());

  async function copyLink() {
    const r = app.attempt(() => demo.share_token());
    if (!r.ok) {
      app.notice.show(`No share link: ${r.error}`, 'error');
      return;
    }
    // While the robot stands, making the link restarts the set-up from it (what the link
    // opens with): the panels read the system again, and the log starts afresh with the
    // restarted system's events (its clock starts again too).
    if (!JSON.parse(demo.telemetry_json()).driving) {
      app.log.clear();
      app.log.update();
      app.log.page('Set-up restarted from the share link (what the link opens with).', 'info');
    }
    app.emit('changed');
    app.stage.draw();
    const url = `${location.origin}${location.pathname}?share=${r.value}`;
    link.value = url;
    link.hidden = false;
    link.dataset.token = r.value;
    let copied = false;
    try {
      await navigator.clipboard.writeText(url);
      copied = true;
    } catch {
      // Not allowed here (no permission, not a secure context): the field shows it.
    }
    link.focus();
    link.select();
    app.notice.show(copied
      ? 'Share link copied: it opens this scenario with the same start, goal, map edits and parameters.'
      : 'Share link made: copy it from the field under the canvas.', 'success');
  }

  const share = el('button', {
    type: 'button', id: 'share-copy', class: 'secondary',
    title: 'Make a link to this set-up (scenario, start, goal, map edits, changed parameters) and copy it',
    onclick: copyLink,
  }, 'Copy share link');
  const csv = el('button', {
    type: 'button', id: 'export-csv', class: 'secondary', title: 'Download the telemetry history as CSV (one row per sample, header first)',
    onclick: () => {
      const r = app.attempt(() => demo.telemetry_csv());
      if (!r.ok) return app.notice.show(`No telemetry CSV: ${r.error}`, 'error');
      downloadText(r.value, 'rtnav-telemetry.csv', 'text/csv');
    },
  }, 'Telemetry CSV');
  const png = el('button', {
    type: 'button', id: 'export-png', class: 'secondary', title: 'Download the frame on the canvas as PNG',
    onclick: () => canvas.toBlob((blob) => {
      if (blob) download(blob, 'rtnav-frame.png');
      else app.notice.show('The frame could not be saved as PNG.', 'error');
    }, 'image/png'),
  }, 'Frame PNG');

  root.append(
    el('div', { class: 'share-row' }, share, el('span', { class: 'export-label' }, 'Export'), csv, png),
    link,
  );
  app.on('loaded', () => {
    link.hidden = true;
    link.value = '';
  });
}
