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

/**
 * The message for a file the readers rejected: "Cannot read NAME: line N: what" from the reader's
 * "NAME:N: what" (or its message as it is when it names no line).
 */
export function fileReadError(name, message) {
  let rest = String(message);
  if (rest.startsWith(`${name}:`)) rest = rest.slice(name.length + 1).trimStart();
  const line = /^(\d+):\s*/.exec(rest);
  if (line) rest = `line ${line[1]}: ${rest.slice(line[0].length)}`;
  return `Cannot read ${name}: ${rest}`;
}

/**
 * Reads `file` in the worker with the C++ reader for `as` ('points' | 'points2d' | 'mesh'):
 * resolves with the worker's result message, or with {error} (the message to show), or with
 * {cancelled: true} when Cancel dropped the worker meanwhile.
 */
export async function readInWorker(worker, file, as) {
  let msg;
  showFileNote(file.name, []);
  try {
    msg = await worker.request({ type: 'read', as, bytes: await file.arrayBuffer(), name: file.name });
  } catch (err) {
    return err.cancelled ? { cancelled: true } : { error: fileReadError(file.name, err.message) };
  }
  if (msg.type !== 'result') return { error: fileReadError(file.name, msg.message) };
  showFileNote(file.name, msg.warnings ?? []);
  return msg;
}

/**
 * A view's file read in the worker (readInWorker) with the panel kept informed: `ui.error` hidden
 * and "Reading NAME…" in `ui.status` meanwhile. Resolves with the worker's result message, or with
 * null after a failure (`onError(message)` has been told) or Cancel.
 */
export async function readFileForView(worker, file, as, { ui, onError }) {
  ui.error.hidden = true;
  ui.status.textContent = `Reading ${file.name}…`;
  const msg = await readInWorker(worker, file, as);
  if (msg.cancelled) return null;
  if (msg.error) {
    onError(msg.error);
    return null;
  }
  return msg;
}

/**
 * The short note under "Open file…" about what the reader skipped in the file just read
 * ("fcl.obj: skipped 1 unknown OBJ record "648" (first at line 1)"); hidden when it skipped nothing.
 */
export function showFileNote(name, warnings) {
  const note = document.getElementById('file-note');
  if (!note) return;
  note.textContent = warnings.length ? `${name}: ${warnings.join('; ')}` : '';
  note.hidden = warnings.length === 0;
}

/**
 * Shows and selects the hidden "file" option of a view's point-source `select`, named after the
 * file just opened ("from bunny.obj").
 */
export function chooseFileOption(select, name) {
  const option = select.querySelector('option[value="file"]');
  option.hidden = false;
  option.textContent = `from ${name}`;
  select.value = 'file';
}
