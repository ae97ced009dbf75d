import type { PngSize } from '../fileNames';
import { useMessages } from '../i18n/MessagesContext';
import { Segmented } from './Segmented';

/** Props of PngSizeChoice: the chosen PNG size and its setter. */
export interface PngSizeChoiceProps {
  value: PngSize;
  onChange: (size: PngSize) => void;
}

/** The size of exported PNGs: as on screen, twice that, or print (300 dpi). */
export function PngSizeChoice({ value, onChange }: PngSizeChoiceProps) {
  const t = useMessages();
  return (
    <Segmented<PngSize>
      legend={t.exportSize}
      value={value}
      options={[
        { value: 'screen', label: t.sizeScreen },
        { value: '2x', label: t.size2x },
        { value: 'print', label: t.sizePrint },
      ]}
      onChange={onChange}
    />
  );
}
