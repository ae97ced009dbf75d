import './components/base.css';
import './components/embedLayout.css';
import { EmbedLayout } from './components/EmbedLayout';
import { mount } from './mount';
import { applyTokens } from './theme/applyTokens';

applyTokens(document.documentElement.style);
void mount(EmbedLayout);
