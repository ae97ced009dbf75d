import reactHooks from 'eslint-plugin-react-hooks';
import tseslint from 'typescript-eslint';

/** Every feature folder under src/features: each may import only itself, src/shared and the numerics. */
const FEATURES = ['simulator', 'lab', 'export', 'share', 'synthesis', 'forces', 'designs'];
/** A relative import that reaches the app's layers (from a numerics folder). */
const APP_LAYERS = '^(\\.\\./)+(app|features|shared|workers)(/|$)';
/** A relative import from src/shared that reaches above it. */
const ABOVE_SHARED = '^(\\.\\./)+(app|features|workers)(/|$)';

/** Lint: the solver's import boundary (STYLE.md principle 1), type-only imports, hooks rules. */
export default tseslint.config(
  {
    ignores: [
      'dist/**',
      'dist-single/**',
      'dist-element/**',
      'node_modules/**',
      'e2e/artifacts/**',
      'playwright-report/**',
      'test-results/**',
    ],
  },
  ...tseslint.configs.recommended,
  {
    files: ['**/*.{ts,tsx}'],
    rules: {
      '@typescript-eslint/consistent-type-imports': 'error',
      '@typescript-eslint/no-non-null-assertion': 'off',
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_' }],
    },
  },
  {
    // The React Compiler-era hooks rules (eslint-plugin-react-hooks v7 flat config): refs not touched in render,
    // no setState straight inside an effect, pure render, effect events only called from effects.
    files: ['src/**/*.tsx', 'src/**/use*.ts'],
    ...reactHooks.configs.flat['recommended-latest'],
  },
  {
    // useJobClient creates the worker's client in an effect (a worker must not start during render, and the
    // effect's cleanup terminates it) and stores it in state: the one setState in an effect the app keeps.
    files: ['src/shared/jobs/useJobClient.ts'],
    rules: { 'react-hooks/set-state-in-effect': 'off' },
  },
  {
    // Units in one place (src/solver/angles.ts): no hand-written degree conversions or pi arithmetic elsewhere.
    files: ['src/**/*.{ts,tsx}'],
    ignores: ['src/solver/angles.ts'],
    rules: {
      'no-restricted-syntax': [
        'error',
        {
          selector: "MemberExpression[object.name='Math'][property.name='PI']",
          message: 'Use the units module (src/solver/angles.ts): degToRad/radToDeg, PI, TWO_PI, the wraps.',
        },
      ],
    },
  },
  {
    // Numerics (the solver, synthesis, the lab's study): pure, testable in Node, importing nothing of the app.
    files: ['src/solver/**/*.ts', 'src/synthesis/**/*.ts', 'src/study/**/*.ts', 'src/spatial/**/*.ts'],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          patterns: [
            { group: ['react', 'react-dom', 'react/*', 'react-dom/*'], message: 'Numerics are pure: no React.' },
            { group: ['d3-*', 'd3'], message: 'Numerics are pure: no d3.' },
            { regex: APP_LAYERS, message: 'Numerics depend on nothing in the app (app, features, shared, workers).' },
          ],
        },
      ],
      'no-restricted-globals': ['error', 'window', 'document', 'self', 'navigator', 'postMessage', 'performance'],
    },
  },
  {
    // Kits every feature uses: they never know the features, the shell or the workers' entries.
    files: ['src/shared/**/*.{ts,tsx}'],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          patterns: [
            { regex: ABOVE_SHARED, message: 'shared/ never imports a feature, the app shell or a worker entry.' },
          ],
        },
      ],
    },
  },
  ...FEATURES.map((feature) => ({
    // One feature never imports another (they meet in src/app) nor the shell above it.
    files: [`src/features/${feature}/**/*.{ts,tsx}`],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          patterns: [
            {
              regex: `^(\\.\\./)+(${FEATURES.filter((f) => f !== feature).join('|')})(/|$)|(^|/)features/|(^|/)(app|workers)(/|$)`,
              message: `features/${feature} imports only shared kits, numerics and itself; features and workers meet in src/app.`,
            },
          ],
        },
      ],
    },
  })),
);
