// @ts-check
// Share and export: a link that reproduces this set-up (the scenario, where the
// robot starts and goes, the map edits since the scenario was loaded and every parameter
// changed; `share_token`), the telemetry as CSV (`telemetry_csv`) and the frame on the
// canvas as PNG.
import { el } from '../dom.js';
import { download, downloadText } from '../download.js';
import { t, language } from '../i18n.js';

/**
 * @param {HTMLElement} root
 * @param {HTMLCanvasElement} canvas
 * @param {App} app
 */
export function createShare(root, canvas, app) {
  const { demo } = app;

  const link = el('input', {
    type: 'text', id: 'share-link', class: 'share-link', readonly: true, hidden: true,
    'aria-label': t('share.link'), title: t('share.link.title'),
  });
  link.addEventListener('focus', () => link.select());

  async function copyLink() {
    const r = app.attempt(() => demo.share_token());
    if (!r.ok) {
      app.notice.show(t('share.none', { error: r.error }), 'error');
      return;
    }
    // While the robot stands, making the link restarts the set-up from it (what the link
    // opens with): the panels read the system again, and the log starts afresh with the
    // restarted system's events (its clock starts again too).
    if (!demo.telemetry().driving) {
      app.log.clear();
      app.log.update();
      app.log.page(t('share.restarted'), 'info');
    }
    app.emit('changed');
    app.stage.draw();
    const url = `${location.origin}${location.pathname}?lang=${language()}&share=${r.value}`;
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
      ? t('share.copied')
      : t('share.made'), 'success');
  }

  const share = el('button', {
    type: 'button', id: 'share-copy', class: 'secondary',
    title: t('share.copy.title'),
    onclick: copyLink,
  }, t('share.copy'));
  const csv = el('button', {
    type: 'button', id: 'export-csv', class: 'secondary', title: t('share.csv.title'),
    onclick: () => {
      const r = app.attempt(() => demo.telemetry_csv());
      if (!r.ok) return app.notice.show(t('share.csv.none', { error: r.error }), 'error');
      downloadText(r.value ?? '', 'rtnav-telemetry.csv', 'text/csv');
    },
  }, t('share.csv'));
  const png = el('button', {
    type: 'button', id: 'export-png', class: 'secondary', title: t('share.png.title'),
    onclick: () => canvas.toBlob((blob) => {
      if (blob) download(blob, 'rtnav-frame.png');
      else app.notice.show(t('share.png.none'), 'error');
    }, 'image/png'),
  }, t('share.png'));

  root.append(
    el('div', { class: 'share-row' }, share, el('span', { class: 'export-label' }, t('share.export')), csv, png),
    link,
  );
  app.on('loaded', () => {
    link.hidden = true;
    link.value = '';
  });
}
