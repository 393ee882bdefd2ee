import { loadHedge } from 'hedge-mesh/single';
import { scenario } from './scenario.js';

scenario(loadHedge).then(
  (result) => (document.querySelector('#result').textContent = JSON.stringify(result)),
  (error) =>
    (document.querySelector('#result').textContent = JSON.stringify({ error: `${error}` })),
);
