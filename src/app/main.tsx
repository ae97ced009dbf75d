import './base.css';
import './layout.css';
import { AppLayout } from './AppLayout';
import { mount } from './mount';
import { applyTokens } from '../shared/theme/applyTokens';
import { prestartSolverWorker } from '../workers/solverClient';

// The worker's script loads while the first frame renders (the first load on a phone, docs/ARCHITECTURE.md).
prestartSolverWorker();

applyTokens(document.documentElement.style);
void mount(AppLayout);
