/** One object (or instance) to choose for, as {@link allocateShading} sees it. */
export interface AllocationUnit {
  /** Each candidate's cost (any unit, ≥ 0, finite). */
  readonly costs: ArrayLike<number>;
  /** Each candidate's estimated over-budget pixels (≥ 0, finite); at least one candidate has 0. */
  readonly overs: ArrayLike<number>;
  /** The candidate chosen last frame, or −1. */
  readonly previous: number;
}

/** The candidate minimising cost + λ·over (ties: fewer over-budget pixels, then the lower index). */
function best(unit: AllocationUnit, lambda: number): number {
  const { costs, overs } = unit;
  let k = 0;
  let score = Number.POSITIVE_INFINITY;
  for (let c = 0; c < costs.length; c++) {
    const s = lambda === Number.POSITIVE_INFINITY ? overs[c] : costs[c] + lambda * overs[c];
    const tie = lambda === Number.POSITIVE_INFINITY ? costs[c] < costs[k] : overs[c] < overs[k];
    if (s < score || (s === score && tie)) {
      score = s;
      k = c;
    }
  }
  return k;
}

function totalOver(units: readonly AllocationUnit[], choice: Int32Array): number {
  let t = 0;
  for (let i = 0; i < units.length; i++) t += units[i].overs[choice[i]];
  return t;
}

/**
 * The cheapest choice per unit whose over-budget pixels sum to at most `allowance`, with hysteresis.
 *
 * Fresh choice: the candidates minimising cost + λ·over for the smallest price λ (found by bisection) at which
 * the total stays within `allowance / (1 + hysteresis)`. Each unit then keeps last frame's candidate when it
 * is at least as accurate and costs at most (1 + hysteresis)× the fresh one, or when it is cheaper (and less
 * accurate) and the total with every such kept candidate stays within `allowance` (else the kept candidates
 * with the most extra over-budget pixels are dropped first). So a unit crossing a threshold changes its
 * choice once: back only after the total moved by the hysteresis factor.
 * @returns the chosen candidate index per unit.
 */
export function allocateShading(
  units: readonly AllocationUnit[],
  allowance: number,
  hysteresis: number,
): Int32Array {
  const n = units.length;
  const choice = new Int32Array(n);
  const target = allowance / (1 + hysteresis);
  const pick = (lambda: number) => {
    for (let i = 0; i < n; i++) choice[i] = best(units[i], lambda);
    return totalOver(units, choice);
  };
  if (pick(0) > target) {
    let lo = -12;
    let hi = 12;
    if (pick(10 ** hi) > target) {
      pick(Number.POSITIVE_INFINITY);
    } else {
      for (let it = 0; it < 48; it++) {
        const mid = (lo + hi) / 2;
        if (pick(10 ** mid) > target) lo = mid;
        else hi = mid;
      }
      pick(10 ** hi);
    }
  }
  // Hysteresis.
  const fresh = Int32Array.from(choice);
  const cheaperKept: number[] = [];
  for (let i = 0; i < n; i++) {
    const u = units[i];
    const p = u.previous;
    const c = fresh[i];
    if (p < 0 || p >= u.costs.length || p === c) continue;
    if (u.overs[p] <= u.overs[c] && u.costs[p] <= (1 + hysteresis) * u.costs[c]) choice[i] = p;
    else if (u.overs[p] > u.overs[c] && u.costs[p] < u.costs[c]) {
      choice[i] = p;
      cheaperKept.push(i);
    }
  }
  let total = totalOver(units, choice);
  if (total > allowance) {
    cheaperKept.sort(
      (a, b) =>
        units[b].overs[choice[b]] -
        units[b].overs[fresh[b]] -
        (units[a].overs[choice[a]] - units[a].overs[fresh[a]]),
    );
    for (const i of cheaperKept) {
      if (total <= allowance) break;
      total -= units[i].overs[choice[i]] - units[i].overs[fresh[i]];
      choice[i] = fresh[i];
    }
  }
  return choice;
}
