import reactHooks from 'eslint-plugin-react-hooks';
import tseslint from 'typescript-eslint';

/** Lint: the solver's import boundary (STYLE.md principle 1), type-only imports, hooks rules. */
export default tseslint.config(
  { ignores: ['dist/**', 'node_modules/**', 'e2e/artifacts/**', 'playwright-report/**', 'test-results/**'] },
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
    files: ['src/**/*.tsx', 'src/**/use*.ts'],
    plugins: { 'react-hooks': reactHooks },
    rules: { 'react-hooks/rules-of-hooks': 'error', 'react-hooks/exhaustive-deps': 'warn' },
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
    files: ['src/solver/**/*.ts', 'src/lab/**/*.ts'],
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
