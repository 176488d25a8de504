/**
 * The user's model kept across reloads: the file's bytes and name in IndexedDB (a model does not fit in a URL or
 * in localStorage's few MiB). The URL says only `scene: 'model'`; the bytes are this browser's. Every call
 * settles: where IndexedDB is missing or refuses (private windows, quota), saving reports it and loading finds
 * nothing.
 */

const DB = 'shadelab';
const STORE = 'model';
const KEY = 'current';

/** A stored model file. */
export interface StoredModel {
  readonly name: string;
  readonly bytes: ArrayBuffer;
}

function open(): Promise<IDBDatabase> {
  return new Promise((resolve, reject) => {
    if (typeof indexedDB === 'undefined') {
      reject(new Error('this browser has no IndexedDB'));
      return;
    }
    const request = indexedDB.open(DB, 1);
    request.onupgradeneeded = () => request.result.createObjectStore(STORE);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error ?? new Error('IndexedDB refused to open'));
    request.onblocked = () => reject(new Error('IndexedDB is blocked by another tab'));
  });
}

async function run<T>(
  mode: IDBTransactionMode,
  action: (store: IDBObjectStore) => IDBRequest<T>,
): Promise<T> {
  const db = await open();
  try {
    return await new Promise<T>((resolve, reject) => {
      const transaction = db.transaction(STORE, mode);
      const request = action(transaction.objectStore(STORE));
      transaction.oncomplete = () => resolve(request.result);
      transaction.onerror = () => reject(transaction.error ?? new Error('IndexedDB transaction failed'));
      transaction.onabort = () => reject(transaction.error ?? new Error('IndexedDB transaction aborted'));
    });
  } finally {
    db.close();
  }
}

/** Keeps the model for the next visit; resolves to null, or to why it could not be kept. */
export async function saveModel(model: StoredModel): Promise<string | null> {
  try {
    await run('readwrite', (store) => store.put({ name: model.name, bytes: model.bytes }, KEY));
    return null;
  } catch (error) {
    return error instanceof Error ? error.message : String(error);
  }
}

/** The stored model, or null when there is none (or IndexedDB cannot be read: `error` says why). */
export async function loadStoredModel(): Promise<{ model: StoredModel | null; error?: string }> {
  try {
    const value: unknown = await run('readonly', (store) => store.get(KEY));
    const { name, bytes } = (value ?? {}) as Partial<StoredModel>;
    if (typeof name === 'string' && bytes instanceof ArrayBuffer) return { model: { name, bytes } };
    return { model: null };
  } catch (error) {
    return { model: null, error: error instanceof Error ? error.message : String(error) };
  }
}
