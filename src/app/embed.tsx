import './base.css';
import './embedPage.css';
import { EmbedLayout } from './EmbedLayout';
import { mount } from './mount';
import { applyTokens } from '../shared/theme/applyTokens';

applyTokens(document.documentElement.style);
void mount(EmbedLayout);
