import reactHooks from 'eslint-plugin-react-hooks';
import tseslint from 'typescript-eslint';

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
    // Temporary, until its owner's rewrite lands (see the app-shell report): useSolverClient stores the
    // client it creates in an effect.
    files: ['src/components/useSolver.ts'],
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
    files: ['src/solver/**/*.ts', 'src/synthesis/**/*.ts', 'src/lab/**/*.ts'],
    rules: {
      'no-restricted-imports': [
        'error',
        {
          patterns: [
            { group: ['react', 'react-dom', 'react/*', 'react-dom/*'], message: 'The solver is pure: no React.' },
            { group: ['d3-*', 'd3'], message: 'The solver is pure: no d3.' },
            {
              group: ['../components/*', '../render/*', '../charts/*', '../worker/*', '../state/*'],
              message: 'The solver depends on nothing in the app.',
            },
          ],
        },
      ],
      'no-restricted-globals': ['error', 'window', 'document', 'self', 'navigator', 'postMessage', 'performance'],
    },
  },
);
