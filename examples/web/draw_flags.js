// SPDX-License-Identifier: MIT
// The draw flags as the page's checkboxes: each toggles one of World.draw's options, and
// the page draws the next frame with them.

/** [label, World.draw option, checked at load]: shapes and joints on, as the library's
 *  defaults have them. */
const TOGGLES = [
  ['shapes', 'drawShapes', true],
  ['joints', 'drawJoints', true],
  ['joint extras', 'drawJointExtras', false],
  ['bounds', 'drawBounds', false],
  ['mass', 'drawMass', false],
  ['contacts', 'drawContacts', false],
  ['normals', 'drawContactNormals', false],
  ['impulses', 'drawContactImpulses', false],
  ['friction', 'drawFrictionImpulses', false],
  ['graph colours', 'drawGraphColors', false],
  ['islands', 'drawIslands', false],
];

/**
 * Fills `container` with a checkbox per flag (id "flag-<option>") and returns the options
 * object they keep up to date.
 */
export function makeDrawToggles(container) {
  const flags = {};
  for (const [label, option, checked] of TOGGLES) {
    flags[option] = checked;
    const box = Object.assign(document.createElement('input'), { type: 'checkbox', id: `flag-${option}`, checked });
    box.addEventListener('change', () => { flags[option] = box.checked; });
    const text = Object.assign(document.createElement('label'), { htmlFor: box.id, textContent: label });
    const item = document.createElement('span');
    item.append(box, text);
    container.append(item);
  }
  return flags;
}
