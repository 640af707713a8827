import { describe, expect, it } from 'vitest';
import { MAX_PRESOLVE_SECONDS, presolveInTurn, presolveOrder } from '../../web/src/worker/presolve.js';
import { sliderPositions } from '../../web/src/ui/layout-view.js';

const SLIDER = Array.from({ length: 41 }, (_, k) => k / 2);
const noWait = () => Promise.resolve();

describe('presolveOrder', () => {
  it('orders the slider nearest first from the shown alpha, the smaller of two as far first', () => {
    const order = presolveOrder(SLIDER, 5);
    expect(order.slice(0, 6)).toEqual([4.5, 5.5, 4, 6, 3.5, 6.5]);
    expect(order).toHaveLength(40);
    expect(order).not.toContain(5);
    expect(order.at(-1)).toBe(20);
    expect(presolveOrder([3, 1, 3, 2], 0)).toEqual([1, 2, 3]);
  });

  it('takes nothing but a list of finite alphas >= 0 of a sane length', () => {
    expect(presolveOrder(undefined, 5)).toEqual([]);
    expect(presolveOrder('0,1,2', 5)).toEqual([]);
    expect(presolveOrder([0, -1], 5)).toEqual([]);
    expect(presolveOrder([0, Number.NaN], 5)).toEqual([]);
    expect(presolveOrder([0, Infinity], 5)).toEqual([]);
    expect(presolveOrder([0, '1'], 5)).toEqual([]);
    expect(presolveOrder(new Array(1001).fill(1), 5)).toEqual([]);
  });
});

describe('presolveInTurn', () => {
  it('presolves in order until every alpha is solved', async () => {
    const seen = [];
    const done = await presolveInTurn([1, 2, 3], (a) => seen.push(a) > 0, () => true, { yieldTurn: noWait });
    expect(seen).toEqual([1, 2, 3]);
    expect(done).toBe(3);
  });

  it('stops when a request came in, on an error, on an unproven alpha and after a slow one', async () => {
    let wanted = true;
    const seen = [];
    const stopAfterTwo = (a) => {
      seen.push(a);
      if (seen.length === 2) wanted = false;
      return true;
    };
    expect(await presolveInTurn([1, 2, 3], stopAfterTwo, () => wanted, { yieldTurn: noWait })).toBe(2);
    expect(seen).toEqual([1, 2]);

    const throwing = (a) => {
      if (a === 2) throw new Error('limit');
      return true;
    };
    expect(await presolveInTurn([1, 2, 3], throwing, () => true, { yieldTurn: noWait })).toBe(1);
    expect(await presolveInTurn([1, 2, 3], (a) => a !== 2, () => true, { yieldTurn: noWait })).toBe(1);

    let clock = 0;
    const slowSecond = (a) => {
      clock += a === 2 ? 1000 * MAX_PRESOLVE_SECONDS + 1 : 10;
      return true;
    };
    const now = () => clock;
    expect(await presolveInTurn([1, 2, 3], slowSecond, () => true, { yieldTurn: noWait, now })).toBe(2);
  });

  it('takes a request in between two presolves, and stops', async () => {
    const events = [];
    let wanted = true;
    const running = presolveInTurn([1, 2, 3], (a) => events.push(`presolve ${a}`) > 0, () => wanted);
    setTimeout(() => {
      events.push('request');
      wanted = false;
    }, 0);
    await running;
    expect(events).toEqual(['presolve 1', 'request']);
  });
});

describe('sliderPositions', () => {
  it('lists a range input from min to max by step', () => {
    expect(sliderPositions({ min: '0', max: '20', step: '0.5' })).toEqual(SLIDER);
    expect(sliderPositions({ min: '0', max: '1', step: '0.1' })).toEqual([0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]);
    expect(sliderPositions({ min: '0', max: '20', step: 'any' })).toEqual([]);
  });
});
