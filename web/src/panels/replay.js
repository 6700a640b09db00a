// The replay bar (shown while /viz/playback says mode "replay"): play / pause, speed, and a time
// slider over start_t..end_t. Controls send {"op": "x-topay-playback", ...}; while the user drags
// the slider (and briefly after the seek) incoming playback messages do not move it.

import { clock } from '../util/format.js';

const HOLD_AFTER_SEEK_MS = 600;

export class ReplayBar {
  /** @param send (message) => bool ; onSeek(t) after a seek was sent */
  constructor(elements, send, onSeek = () => {}) {
    this.el = elements;
    this.send = send;
    this.dragging = false;
    this.holdUntil = 0;
    this.playback = null;

    const command = (name, extra = {}) => this.send({ op: 'x-topay-playback', command: name, ...extra });
    this.el.play.addEventListener('click', () => command('play'));
    this.el.pause.addEventListener('click', () => command('pause'));
    this.el.speed.addEventListener('change', () => command('speed', { speed: Number(this.el.speed.value) }));

    const slider = this.el.slider;
    const startDrag = () => {
      this.dragging = true;
    };
    slider.addEventListener('pointerdown', startDrag);
    slider.addEventListener('mousedown', startDrag);
    slider.addEventListener('touchstart', startDrag, { passive: true });
    slider.addEventListener('keydown', startDrag);
    slider.addEventListener('input', () => {
      this.dragging = true;
      this.#label(Number(slider.value));
    });
    slider.addEventListener('change', () => {
      const t = Number(slider.value);
      this.dragging = false;
      this.holdUntil = performance.now() + HOLD_AFTER_SEEK_MS;
      if (command('seek', { t })) onSeek(t);
      this.#label(t);
    });
    const endDrag = () => {
      // 'change' follows a real move; a click without a move ends the drag here.
      setTimeout(() => {
        this.dragging = false;
      }, 0);
    };
    slider.addEventListener('pointerup', endDrag);
    slider.addEventListener('blur', endDrag);
  }

  update(playback) {
    this.playback = playback;
    const replay = playback.mode === 'replay';
    this.el.bar.hidden = !replay;
    this.el.mode.textContent = replay ? 'REPLAY' : 'LIVE';
    this.el.mode.className = replay ? 'badge replay' : 'badge live';
    if (!replay) return;
    this.el.play.disabled = !!playback.playing;
    this.el.pause.disabled = !playback.playing;
    if (document.activeElement !== this.el.speed) {
      const speed = String(playback.speed);
      if ([...this.el.speed.options].some((o) => o.value === speed)) this.el.speed.value = speed;
    }
    const slider = this.el.slider;
    if (this.dragging || performance.now() < this.holdUntil) return;
    slider.min = String(playback.start_t);
    slider.max = String(playback.end_t);
    slider.value = String(playback.t);
    this.#label(playback.t);
  }

  #label(t) {
    const p = this.playback;
    const since = p ? (t - p.start_t).toFixed(1) : '—';
    const length = p ? (p.end_t - p.start_t).toFixed(1) : '—';
    this.el.timeLabel.textContent = `${clock(t)}  (${since} / ${length} s)`;
  }
}
