import './components/base.css';
import './components/layout.css';
import { AppLayout } from './components/AppLayout';
import { mount } from './mount';
import { applyTokens } from './theme/applyTokens';

applyTokens(document.documentElement.style);
void mount(AppLayout);
