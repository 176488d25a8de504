// The vitest reporter of `npm test`: the same text on every run of the same code. vitest's default reporter
// prints files as parallel workers finish them, with durations and a "slow test" line past a time threshold;
// this one waits for the end of the run and prints, sorted by file: each file's result and test count, what its
// tests printed (a fuzz suite's closing line with its seed), then every failure with its error, and the totals.
// No durations, no start time. Used by scripts/test.mjs and scripts/three-compat.mjs.
import { relative } from 'node:path';

/** @typedef {import('vitest/node').TestModule} TestModule */
/** @typedef {import('vitest/node').Reporter} Reporter */

/** @implements {Reporter} */
export default class DeterministicReporter {
  /** @type {import('vitest').UserConsoleLog[]} */
  #logs = [];
  #root = process.cwd();

  /** @param {import('vitest/node').Vitest} vitest */
  onInit(vitest) {
    this.#root = vitest.config.root;
  }

  /** @param {import('vitest').UserConsoleLog} log */
  onUserConsoleLog(log) {
    this.#logs.push(log);
  }

  /**
   * @param {ReadonlyArray<TestModule>} modules
   * @param {ReadonlyArray<{ message?: string, stack?: string }>} unhandled
   */
  onTestRunEnd(modules, unhandled) {
    const sorted = [...modules].sort((a, b) =>
      a.moduleId < b.moduleId ? -1 : a.moduleId > b.moduleId ? 1 : 0,
    );
    const out = [];
    const failures = [];
    let files = 0;
    let failedFiles = 0;
    const counts = { passed: 0, failed: 0, skipped: 0 };
    for (const module of sorted) {
      const name = relative(this.#root, module.moduleId);
      const tests = [...module.children.allTests()];
      const failed = tests.filter((t) => t.result().state === 'failed');
      for (const t of tests) {
        const state = t.result().state;
        if (state === 'passed') counts.passed++;
        else if (state === 'failed') counts.failed++;
        else counts.skipped++;
      }
      const moduleErrors = module.errors();
      const ok = failed.length === 0 && moduleErrors.length === 0 && module.state() !== 'failed';
      files++;
      if (!ok) failedFiles++;
      out.push(
        `${ok ? '✓' : '✗'} ${name} (${tests.length} tests${failed.length ? `, ${failed.length} failed` : ''})`,
      );
      // Logs in the order this file's tests made them: one file runs in one worker, in order.
      for (const log of this.#logs) {
        if (log.taskId === module.id || log.taskId?.startsWith(`${module.id}_`)) {
          for (const line of log.content.replace(/\n$/, '').split('\n')) out.push(`    ${line}`);
        }
      }
      for (const error of moduleErrors) failures.push(`${name}\n${error.stack ?? error.message}`);
      for (const t of failed) {
        const errors = t.result().errors ?? [];
        failures.push(
          `${name} > ${t.fullName}\n${errors.map((e) => [e.stack ?? e.message, e.diff].filter(Boolean).join('\n')).join('\n')}`,
        );
      }
    }
    for (const error of unhandled) failures.push(`unhandled error\n${error.stack ?? error.message}`);
    if (failures.length) {
      out.push('', `── ${failures.length} failure${failures.length === 1 ? '' : 's'} ──`);
      for (const f of failures) out.push('', f);
    }
    out.push(
      '',
      `Test files ${files - failedFiles} passed, ${failedFiles} failed`,
      `Tests      ${counts.passed} passed, ${counts.failed} failed, ${counts.skipped} skipped`,
    );
    process.stdout.write(`${out.join('\n')}\n`);
  }
}
