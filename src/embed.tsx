import './styles.css';
import { EmbedLayout } from './components/EmbedLayout';
import { mount } from './mount';

mount(EmbedLayout);
