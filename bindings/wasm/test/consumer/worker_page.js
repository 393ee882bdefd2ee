// Runs the scenario in a module worker (worker.js) and shows what it computed.
const show = (value) => (document.querySelector('#result').textContent = JSON.stringify(value));
const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
worker.onmessage = (event) => show(event.data);
worker.onerror = (event) => show({ error: `worker: ${event.message}` });
