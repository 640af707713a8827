// Files come in two ways: dropped anywhere on the page, or picked with the file input.

/** Calls onFiles(FileList) for files dropped on `target` or chosen in `input`. */
export function acceptFiles({ target, input, onFiles }) {
  input.addEventListener('change', () => {
    if (input.files.length > 0) onFiles([...input.files]);
    input.value = ''; // so that choosing the same file again loads it again
  });

  const hasFiles = (event) => event.dataTransfer?.types.includes('Files');
  let depth = 0; // dragenter/dragleave fire for every child element crossed
  const setDragging = (dragging) => target.classList.toggle('dragging', dragging);
  target.addEventListener('dragenter', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    depth++;
    setDragging(true);
  });
  target.addEventListener('dragleave', () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) setDragging(false);
  });
  target.addEventListener('dragover', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    event.dataTransfer.dropEffect = 'copy';
  });
  target.addEventListener('drop', (event) => {
    event.preventDefault();
    depth = 0;
    setDragging(false);
    onFiles([...event.dataTransfer.files]);
  });
}
