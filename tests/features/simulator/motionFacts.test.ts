import { describe, expect, it } from 'vitest';
import { motionFacts } from '../../../src/features/simulator/motionFacts';
import { messagesEn } from '../../../src/shared/i18n/messagesEn';

describe('motionFacts', () => {
  it('shows ω3 of 1e-17 rad/s beside ω2 = 10 rad/s as 0, with no direction for a noise speed', () => {
    const noise = { vx: 1e-17, vy: -1e-17, ax: 5, ay: 0 };
    const facts = motionFacts(
      {
        input: { omega2: 10, alpha2: 0 },
        rates: { omega3: 1e-17, omega4: -2.5, alpha3: 100, alpha4: -3e-15 },
        A: { vx: 0, vy: 10, ax: -100, ay: 0 },
        B: noise,
        P: { vx: 3, vy: 4, ax: 0, ay: 0 },
        limit: false,
      },
      messagesEn,
    );
    const value = (k: string) => facts.find((f) => f.key === k)?.value;
    expect(value('omega3')).toBe('0 rad/s');
    expect(value('omega4')).toBe('\u22122.5 rad/s');
    expect(value('alpha4')).toBe('0 rad/s²');
    expect(value('vB')).toMatch(/^0 /);
    expect(value('vP')).toMatch(/^5 .*53\.1°/);
  });
});
