import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { TradeoffApp } from './TradeoffApp';

const root = document.getElementById('root');
if (root === null) throw new Error('tradeoff.html needs a #root element');
createRoot(root).render(
  <StrictMode>
    <TradeoffApp />
  </StrictMode>,
);
