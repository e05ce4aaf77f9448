// Panel helpers shared by the views.

/**
 * Shows `message` in the view's error box (red, role=alert); also on the console when `logged`
 * (failures of the page or the library, not input the user can fix).
 */
export function showError(el, message, logged) {
  if (logged) console.error(`[hullkit] ${message}`);
  el.textContent = message;
  el.hidden = false;
}
