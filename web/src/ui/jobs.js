import { PAGE_ERROR_KINDS } from '../worker/protocol.js';

/**
 * Runs worker jobs one at a time, with their progress and errors in the status line. Starting a job
 * while another runs cancels the other: the page always shows the result of the last request.
 */
export class Jobs {
  constructor(client, status) {
    this.client = client;
    this.status = status;
    this.current = 0;
  }

  /**
   * start(onProgress) -> Promise of the job's result. Resolves with the result, or with undefined
   * when the job failed (the error is shown), was cancelled or was replaced by a newer job.
   */
  async run(label, start) {
    if (this.client.busy) this.client.cancel();
    const job = ++this.current;
    const isCurrent = () => job === this.current;
    this.status.clearMessage();
    this.status.showProgress(label, 0);
    try {
      const result = await start((stage, fraction) => {
        if (isCurrent()) this.status.showProgress(stage, fraction);
      });
      if (!isCurrent()) return undefined;
      this.status.hideProgress();
      return result;
    } catch (error) {
      if (!isCurrent()) return undefined;
      this.status.hideProgress();
      if (error?.kind === PAGE_ERROR_KINDS.cancelled) {
        this.status.showNotice('Cancelled.', 'The view keeps what it showed before.');
      } else {
        this.status.showError(error);
      }
      return undefined;
    }
  }
}
