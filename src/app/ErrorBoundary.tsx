import './ErrorBoundary.css';
import { Component } from 'react';
import type { ErrorInfo, ReactNode } from 'react';
import type { Messages } from '../shared/i18n/messages';

/** Props of ErrorBoundary: the strings to show and what Reset does. */
export interface ErrorBoundaryProps {
  messages: Messages;
  onReset: () => void;
  children: ReactNode;
}

interface ErrorBoundaryState {
  error: Error | null;
}

/** Shows a readable message with a reset button instead of a blank page when rendering throws. */
export class ErrorBoundary extends Component<ErrorBoundaryProps, ErrorBoundaryState> {
  override state: ErrorBoundaryState = { error: null };

  static getDerivedStateFromError(error: Error): ErrorBoundaryState {
    return { error };
  }

  override componentDidCatch(error: Error, info: ErrorInfo): void {
    console.error('Four-bar linkage lab crashed:', error, info.componentStack);
  }

  override render() {
    const { error } = this.state;
    if (!error) return this.props.children;
    const t = this.props.messages;
    return (
      <div className="error-page" role="alert">
        <h1>{t.errorTitle}</h1>
        <p>{t.errorBody}</p>
        <pre className="error-detail">{error.message}</pre>
        <button
          type="button"
          className="btn btn-primary"
          onClick={() => {
            this.setState({ error: null });
            this.props.onReset();
          }}
        >
          {t.errorReset}
        </button>
      </div>
    );
  }
}
