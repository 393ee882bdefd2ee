// A module worker that loads hedge-mesh and runs the scenario off the page's thread.
import { loadHedge } from 'hedge-mesh';
import { scenario } from './scenario.js';

scenario(loadHedge).then(
  (result) => postMessage(result),
  (error) => postMessage({ error: `${error}` }),
);
