// A grid of cards that draws only the rows in view, so that thousands of cards scroll as fast as
// ten. Cards have one fixed size; as many columns as fit the grid's width; the grid scrolls inside
// its own element. Arrow keys move between cards, Enter opens the one the keyboard is on.
import { oncePerFrame, scrollToBand, visibleRange } from './virtual-list.js';

/**
 * root: the element to turn into the grid (it gets the scroll and the keys); cardWidth and
 * cardHeight in CSS pixels, gap between cards; fillCard(element, item) builds an item's card into
 * an empty element; keyOf(item) names an item; onOpen(item) when the user opens one with the keys
 * (a card's own link opens it on click).
 */
export class VirtualGrid {
  constructor(root, { cardWidth, cardHeight, gap, fillCard, keyOf, onOpen }) {
    Object.assign(this, { root, cardWidth, cardHeight, gap, fillCard, keyOf, onOpen });
    this.items = [];
    this.columns = 1;
    this.active = -1;
    this.requestDraw = oncePerFrame(() => this.draw());
    this.drawn = new Map(); // key -> card element, reused while it stays in view
    root.setAttribute('role', 'grid');
    root.tabIndex = 0;
    this.spacer = document.createElement('div');
    this.spacer.className = 'virtual-spacer';
    this.spacer.setAttribute('role', 'presentation');
    root.replaceChildren(this.spacer);
    root.addEventListener('scroll', () => this.requestDraw());
    root.addEventListener('keydown', (event) => this.onKey(event));
    new ResizeObserver(() => this.requestDraw()).observe(root);
  }

  get rowHeight() {
    return this.cardHeight + this.gap;
  }

  /** Shows a new list of items, scrolled to the top. */
  setItems(items) {
    this.items = items;
    this.active = items.length > 0 ? 0 : -1;
    this.root.scrollTop = 0;
    this.drawn.clear();
    this.draw();
  }

  onKey(event) {
    const page = Math.max(1, Math.floor(this.root.clientHeight / this.rowHeight) - 1) * this.columns;
    const steps = {
      ArrowRight: 1,
      ArrowLeft: -1,
      ArrowDown: this.columns,
      ArrowUp: -this.columns,
      PageDown: page,
      PageUp: -page,
    };
    const last = this.items.length - 1;
    if (event.key in steps || event.key === 'Home' || event.key === 'End') {
      event.preventDefault();
      const target = event.key === 'Home' ? 0 : event.key === 'End' ? last : this.active + steps[event.key];
      this.moveTo(Math.min(last, Math.max(0, target)));
    } else if (event.key === 'Enter' && this.items[this.active]) {
      event.preventDefault();
      this.onOpen(this.items[this.active]);
    }
  }

  moveTo(index) {
    if (index < 0 || index >= this.items.length) return;
    this.active = index;
    const top = Math.floor(index / this.columns) * this.rowHeight;
    scrollToBand(this.root, top, top + this.rowHeight);
    this.draw();
  }

  draw() {
    const width = this.root.clientWidth;
    const columns = Math.max(1, Math.floor((width + this.gap) / (this.cardWidth + this.gap)));
    if (columns !== this.columns) this.drawn.clear();
    this.columns = columns;
    const rows = Math.ceil(this.items.length / columns);
    this.spacer.style.height = `${rows * this.rowHeight}px`;
    const { first, last } = visibleRange(this.root.scrollTop, this.root.clientHeight, this.rowHeight, rows);
    const cards = [];
    const kept = new Map();
    for (let index = first * columns; index < Math.min(this.items.length, last * columns); index++) {
      const card = this.card(index);
      kept.set(this.keyOf(this.items[index]), card);
      cards.push(card);
    }
    this.drawn = kept;
    this.spacer.replaceChildren(...cards);
    this.root.setAttribute('aria-rowcount', String(rows));
  }

  card(index) {
    const item = this.items[index];
    const key = this.keyOf(item);
    let card = this.drawn.get(key);
    if (!card) {
      card = document.createElement('div');
      card.setAttribute('role', 'gridcell');
      this.fillCard(card, item);
    }
    const column = index % this.columns;
    const row = Math.floor(index / this.columns);
    // The columns centred in the grid's width.
    const spare = this.root.clientWidth - (this.columns * (this.cardWidth + this.gap) - this.gap);
    const left = Math.max(0, Math.floor(spare / 2));
    card.style.left = `${left + column * (this.cardWidth + this.gap)}px`;
    card.style.top = `${row * this.rowHeight}px`;
    card.style.width = `${this.cardWidth}px`;
    card.style.height = `${this.cardHeight}px`;
    card.classList.toggle('active', index === this.active);
    return card;
  }
}
