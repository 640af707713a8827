// A listbox that draws only the rows in view, so that thousands of entries scroll as fast as ten.
// Rows have one fixed height; the list scrolls inside its own element.

const OVERSCAN = 6; // rows drawn beyond each edge of the view, so that a fast scroll shows no gap

/** The rows [first, last) to draw for a scroll position, clamped to [0, count). */
export function visibleRange(scrollTop, viewHeight, rowHeight, count) {
  const first = Math.max(0, Math.floor(scrollTop / rowHeight) - OVERSCAN);
  const last = Math.min(count, Math.ceil((scrollTop + viewHeight) / rowHeight) + OVERSCAN);
  return { first, last: Math.max(first, last) };
}

/** Scrolls `root` just enough that the band [top, bottom) of its content is in view. */
export function scrollToBand(root, top, bottom) {
  if (top < root.scrollTop) root.scrollTop = top;
  else if (bottom > root.scrollTop + root.clientHeight) root.scrollTop = bottom - root.clientHeight;
}

/** fn, called at most once per animation frame however often the returned function is. */
export function oncePerFrame(fn) {
  let pending = false;
  return () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      fn();
    });
  };
}

/**
 * root: an element with an id, to turn into the listbox (it gets the scroll, role and keys);
 * rowHeight in CSS pixels; fillRow(element, item) writes an item into a row as text;
 * keyOf(item) names an item; onChoose(item) when the user picks one (click, Enter, Space).
 */
export class VirtualList {
  constructor(root, { rowHeight, fillRow, keyOf, onChoose }) {
    Object.assign(this, { root, rowHeight, fillRow, keyOf, onChoose });
    this.items = [];
    this.active = -1; // the row the keyboard is on
    this.chosenKey = null;
    this.requestDraw = oncePerFrame(() => this.draw());
    root.setAttribute('role', 'listbox');
    root.tabIndex = 0;
    this.spacer = document.createElement('div');
    this.spacer.className = 'virtual-spacer';
    this.spacer.setAttribute('role', 'presentation');
    root.replaceChildren(this.spacer);
    root.addEventListener('scroll', () => this.requestDraw());
    root.addEventListener('keydown', (event) => this.onKey(event));
    root.addEventListener('click', (event) => this.onClick(event));
    new ResizeObserver(() => this.requestDraw()).observe(root);
  }

  /** Shows a new list of items, scrolled to the chosen one when it is there, else to the top. */
  setItems(items) {
    this.items = items;
    this.spacer.style.height = `${items.length * this.rowHeight}px`;
    this.root.scrollTop = 0;
    this.active = items.length > 0 ? 0 : -1;
    this.setChosen(this.chosenKey);
  }

  /** Marks the item named `key` as chosen (null for none) and scrolls it into view. */
  setChosen(key) {
    this.chosenKey = key;
    const index = this.indexOfKey(key);
    if (index >= 0) this.moveTo(index);
    else this.draw();
  }

  indexOfKey(key) {
    return key === null ? -1 : this.items.findIndex((item) => this.keyOf(item) === key);
  }

  onKey(event) {
    const page = Math.max(1, Math.floor(this.root.clientHeight / this.rowHeight) - 1);
    const last = this.items.length - 1;
    const targets = {
      ArrowDown: this.active + 1,
      ArrowUp: this.active - 1,
      PageDown: this.active + page,
      PageUp: this.active - page,
      Home: 0,
      End: last,
    };
    if (event.key in targets) {
      event.preventDefault();
      this.moveTo(Math.min(last, Math.max(0, targets[event.key])));
    } else if ((event.key === 'Enter' || event.key === ' ') && this.items[this.active]) {
      event.preventDefault();
      this.onChoose(this.items[this.active]);
    }
  }

  onClick(event) {
    const row = event.target.closest('[role=option]');
    if (!row) return;
    this.active = Number(row.dataset.index);
    this.onChoose(this.items[this.active]);
  }

  // Makes row `index` the active one and scrolls it just into view.
  moveTo(index) {
    if (index < 0 || index >= this.items.length) return;
    this.active = index;
    const top = index * this.rowHeight;
    scrollToBand(this.root, top, top + this.rowHeight);
    this.draw();
  }

  draw() {
    const { first, last } = visibleRange(this.root.scrollTop, this.root.clientHeight, this.rowHeight, this.items.length);
    const rows = [];
    for (let index = first; index < last; index++) rows.push(this.row(index));
    this.spacer.replaceChildren(...rows);
    const activeRow = rows.find((row) => Number(row.dataset.index) === this.active);
    if (activeRow) this.root.setAttribute('aria-activedescendant', activeRow.id);
    else this.root.removeAttribute('aria-activedescendant');
  }

  row(index) {
    const item = this.items[index];
    const row = document.createElement('div');
    row.setAttribute('role', 'option');
    row.id = `${this.root.id}-option-${index}`;
    row.dataset.index = String(index);
    row.style.top = `${index * this.rowHeight}px`;
    row.setAttribute('aria-selected', String(this.keyOf(item) === this.chosenKey));
    row.setAttribute('aria-setsize', String(this.items.length));
    row.setAttribute('aria-posinset', String(index + 1));
    row.classList.toggle('active', index === this.active);
    this.fillRow(row, item);
    return row;
  }
}
