import './base.css';
import './layout.css';
import { AppLayout } from './AppLayout';
import { mount } from './mount';
import { applyTokens } from '../shared/theme/applyTokens';

applyTokens(document.documentElement.style);
void mount(AppLayout);
