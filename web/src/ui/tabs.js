/**
 * The mode tabs. modes: [{ id, label }]; onSelect(id) when the user picks another tab.
 * Returns select(id), which marks the active tab.
 */
export function createTabs(nav, modes, onSelect) {
  const buttons = modes.map(({ id, label }) => {
    const button = document.createElement('button');
    button.type = 'button';
    button.setAttribute('role', 'tab');
    button.dataset.mode = id;
    button.textContent = label;
    button.addEventListener('click', () => onSelect(id));
    return button;
  });
  nav.replaceChildren(...buttons);
  return function select(id) {
    for (const button of buttons) button.setAttribute('aria-selected', String(button.dataset.mode === id));
  };
}
