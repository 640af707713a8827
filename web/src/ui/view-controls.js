import GUI from 'lil-gui';

/**
 * The view settings panel (lil-gui) inside `container`.
 * settings: { shading: 'flat'|'smooth', wireframe: bool }, changed in place;
 * onChange(settings) after every change. Returns { update(settings) } to show new values.
 */
export function createViewControls(container, settings, onChange) {
  const gui = new GUI({ container, title: 'View' });
  gui
    .add(settings, 'shading', { Flat: 'flat', Smooth: 'smooth' })
    .name('Shading')
    .onChange(() => onChange(settings));
  gui
    .add(settings, 'wireframe')
    .name('Wireframe')
    .onChange(() => onChange(settings));
  return {
    update(values) {
      Object.assign(settings, values);
      gui.controllersRecursive().forEach((controller) => controller.updateDisplay());
    },
  };
}
