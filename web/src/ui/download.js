/** Offers data (bytes or text) to the user as a file download named fileName. */
export function downloadBytes(data, fileName, type = 'application/octet-stream') {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

/** A safe download name from a mesh name: its base name, other characters replaced by '_'. */
export function downloadName(meshName, extension) {
  const base = String(meshName ?? '')
    .split(/[\\/]/)
    .pop()
    .replace(/\.[^.]*$/, '')
    .replace(/[^A-Za-z0-9_.-]+/g, '_')
    .replace(/^[._]+/, '')
    .slice(0, 80);
  return `${base || 'tessera'}.${extension}`;
}
