// The page's status line: progress of the running job with its Cancel button, and the last error
// or notice in plain words. Messages are set as text, never as markup.

const ERROR_TITLES = {
  parse: 'The input could not be read',
  input: 'The input cannot be used',
  topology: 'The mesh has a connectivity Tessera cannot use',
  geometry: 'The mesh has unusable geometry',
  limit: 'The input is beyond a limit',
  unsupported: 'This cannot be opened',
  crash: 'The computation stopped',
  internal: 'Something went wrong inside Tessera',
};

export class Status {
  /** root: the element holding [data-role=progress|stage|bar|cancel|message|message-title|message-text|dismiss]. */
  constructor(root, { onCancel }) {
    this.part = (role) => root.querySelector(`[data-role=${role}]`);
    this.part('cancel').addEventListener('click', onCancel);
    this.part('dismiss').addEventListener('click', () => this.clearMessage());
  }

  showProgress(stage, fraction) {
    this.part('progress').hidden = false;
    this.part('stage').textContent = stage;
    this.part('bar').value = Math.min(1, Math.max(0, Number(fraction) || 0));
  }

  hideProgress() {
    this.part('progress').hidden = true;
  }

  /** An error from a job (an Error with a protocol `kind`) or from the page itself. */
  showError(error) {
    this.showMessage('error', ERROR_TITLES[error?.kind] ?? 'Error', error?.message ?? String(error));
  }

  showNotice(title, text = '') {
    this.showMessage('notice', title, text);
  }

  showMessage(level, title, text) {
    const message = this.part('message');
    message.dataset.level = level;
    message.setAttribute('role', level === 'error' ? 'alert' : 'status');
    this.part('message-title').textContent = title;
    this.part('message-text').textContent = text;
    message.hidden = false;
  }

  clearMessage() {
    this.part('message').hidden = true;
  }
}
