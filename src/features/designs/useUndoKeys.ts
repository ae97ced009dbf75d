import { useEffect } from 'react';
import { isTextField } from '../../shared/ui/textField';

/**
 * Ctrl+Z (Cmd+Z on a Mac) undoes, Ctrl+Shift+Z, Cmd+Shift+Z and Ctrl+Y redo, anywhere on the page but in a
 * text field, where the browser's own undo of the typed text stays.
 */
export function useUndoKeys(undo: () => void, redo: () => void): void {
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (!(e.ctrlKey || e.metaKey) || e.altKey || e.isComposing || isTextField(e.target)) return;
      const key = e.key.toLowerCase();
      const isRedo = (key === 'z' && e.shiftKey) || (key === 'y' && e.ctrlKey && !e.shiftKey);
      const isUndo = key === 'z' && !e.shiftKey;
      if (!isUndo && !isRedo) return;
      e.preventDefault();
      if (isRedo) redo();
      else undo();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [undo, redo]);
}
