import './styles.css';
import { AppLayout } from './components/AppLayout';
import { mount } from './mount';

mount(AppLayout);
