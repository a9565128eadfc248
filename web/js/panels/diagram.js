// The system diagram: each component as the RT System Editor draws it, a block filled with
// its state's colour and its instance name below. A dot inside flashes on every beat.
// (Later issues draw the whole system here, with ports and connections.)
import { setText } from '../dom.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attrs) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, String(v));
  return node;
}

export function createDiagram(root, host) {
  const drawing = svg('svg', { viewBox: '0 0 240 170', class: 'rtc-diagram', role: 'img' });
  const block = svg('rect', { x: 70, y: 20, width: 100, height: 100, rx: 8, class: 'rtc-block' });
  const pulse = svg('circle', { cx: 120, cy: 70, r: 14, class: 'rtc-pulse' });
  const label = svg('text', { x: 120, y: 148, 'text-anchor': 'middle', class: 'rtc-label' });
  drawing.append(block, pulse, label);
  root.append(drawing);

  let beats = host.beats();
  return {
    update() {
      block.setAttribute('fill', host.state_colour());
      setText(label, host.name());
      drawing.setAttribute('aria-label', `${host.name()}: ${host.state()}`);
      const now = host.beats();
      if (now !== beats) {
        beats = now;
        // Restart the flash animation.
        pulse.classList.remove('beat');
        void pulse.getBoundingClientRect();
        pulse.classList.add('beat');
      }
    },
  };
}
