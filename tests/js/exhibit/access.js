// Issue 31, item 5: access (docs/web.md). Play within 15 Tab presses from the top; the closed
// drawer out of the tab order; every panel part focusable, named, its focus visible; WCAG AA
// contrast (4.5:1) for the text of lamps and relays on and off, buttons, captions, hints and
// labels; prefers-reduced-motion: no glow, no transition or animation, and the page's flag set.
'use strict';

// WCAG 2.x relative luminance and contrast of "rgb(a)(...)" colours; text with alpha is laid
// over its background first.
function parse(c) {
  const m = /rgba?\(([^)]+)\)/.exec(c);
  const [r, g, b, a = 1] = m[1].split(/[ ,/]+/).filter(Boolean).map(Number);
  return [r, g, b, a];
}
function over([r, g, b, a], [R, G, B]) {
  return [r * a + R * (1 - a), g * a + G * (1 - a), b * a + B * (1 - a), 1];
}
function luminance([r, g, b]) {
  const lin = (v) => { v /= 255; return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4; };
  return 0.2126 * lin(r) + 0.7152 * lin(g) + 0.0722 * lin(b);
}
function contrast(fg, bg) {
  const [l1, l2] = [luminance(fg), luminance(bg)].sort((a, b) => b - a);
  return (l1 + 0.05) / (l2 + 0.05);
}

module.exports = async function access(t) {
  const { check } = t;
  const page = await t.open('laptop');
  await page.waitForFunction(() => !document.getElementById('play').disabled);

  // ---- Play within 15 Tab presses from the top of the page
  let presses = 0;
  let at = '';
  while (presses < 40) {
    await page.keyboard.press('Tab');
    presses++;
    at = await page.evaluate(() => document.activeElement.id);
    if (at === 'play') break;
  }
  console.log(`Play is reached after ${presses} Tab presses from the top`);
  check(at === 'play' && presses <= 15, 'Play within 15 Tab presses from the top', `${presses} presses, at #${at}`);

  // In field-by-field mode, the drawer open (4,661 tab stops before Play before issue 31):
  // the viewer comes first, so Play is as near. Counted from the first stop, the skip link.
  await page.click('#deck-drawer > summary');
  await page.click('#tab-fields');
  await page.waitForFunction(() => document.querySelectorAll('#fields input').length > 10);
  await page.evaluate(() => document.querySelector('a.skip').focus());
  let fieldPresses = 1;
  for (; fieldPresses < 40; fieldPresses++) {
    if (await page.evaluate(() => document.activeElement.id === 'play')) break;
    await page.keyboard.press('Tab');
  }
  console.log(`field by field, drawer open: Play after ${fieldPresses} Tab presses`);
  check(fieldPresses <= 15, 'Play within 15 Tab presses in field-by-field mode with the drawer open', `${fieldPresses}`);
  await page.click('#tab-listing');
  await page.evaluate(() => { document.getElementById('deck-drawer').open = false; });

  // ---- the closed drawer is out of the tab order: Tab from its summary leaves it
  const drawer = await page.evaluate(() => {
    const d = document.getElementById('deck-drawer');
    d.querySelector('summary').focus();
    return d.open;
  });
  await page.keyboard.press('Tab');
  const after = await page.evaluate(() => {
    const a = document.activeElement;
    return { inside: document.getElementById('deck-drawer').contains(a) && a.tagName !== 'SUMMARY', what: a.tagName + '#' + a.id };
  });
  check(!drawer && !after.inside, 'the closed drawer\'s fields are not in the tab order', `Tab from its summary goes to ${after.what}`);

  // ---- every panel part: focusable, named, and Tab walks through them
  const parts = await page.evaluate(() => {
    const all = [...document.querySelectorAll('#panel .relay, #panel .dial, #panel .lamp')];
    const bad = all.filter((e) => !(e.tabIndex >= 0) || !(e.getAttribute('aria-label') || '').trim() || !e.getAttribute('role'));
    return { n: all.length, bad: bad.length, example: bad.slice(0, 3).map((e) => e.outerHTML.slice(0, 120)),
             names: all.slice(0, 3).map((e) => e.getAttribute('aria-label')) };
  });
  check(parts.n > 500 && parts.bad === 0, 'every panel part is focusable (tabindex 0, role) and has an accessible name',
        `${parts.n} parts, ${parts.bad} without; e.g. ${parts.names.join(' | ')} ${parts.example.join(' ')}`);
  // Tab from the first part lands on the next part: the panel is walked by keyboard.
  await page.evaluate(() => document.querySelector('#panel [data-signal]').focus());
  await page.keyboard.press('Tab');
  const second = await page.evaluate(() => document.activeElement.matches('#panel .relay, #panel .dial, #panel .lamp'));
  check(second, 'Tab moves from one panel part to the next');

  // ---- focus is visible: the outline of a focused part and button differs from the unfocused
  const focusLook = await page.evaluate(() => {
    const look = (e) => { const s = getComputedStyle(e); return `${s.outlineStyle} ${s.outlineWidth} ${s.outlineColor} | ${s.boxShadow}`; };
    const out = [];
    for (const sel of ['#panel .relay', '#panel .dial', '#panel .lamp', '#play', '.speeds button', '#deck-drawer > summary', '.masthead .more > summary']) {
      const e = document.querySelector(sel);
      document.body.focus();
      e.blur();
      const before = look(e);
      e.focus();
      const visible = e.matches(':focus-visible');
      const now = look(e);
      const width = parseFloat(getComputedStyle(e).outlineWidth);
      out.push({ sel, visible, differs: before !== now, width, now });
      e.blur();
    }
    return out;
  });
  for (const f of focusLook) {
    check(f.visible && f.differs && f.width >= 2, `focus visible on ${f.sel}`, f.now);
  }

  // ---- contrast (WCAG AA 4.5:1) of text on its effective background, states included
  const samples = await page.evaluate(() => {
    const bg = (e) => {
      // The backgrounds from the element up to the first opaque one, composed.
      const layers = [];
      for (let x = e; x; x = x.parentElement) {
        const c = getComputedStyle(x).backgroundColor;
        const a = /rgba\(.*,\s*([\d.]+)\)/.exec(c);
        if (c === 'transparent' || (a && Number(a[1]) === 0)) continue;
        layers.push(c);
        if (!a) break;
      }
      layers.push('rgb(255, 255, 255)');
      return layers.reverse();
    };
    const take = (what, e) => ({ what, color: getComputedStyle(e).color, layers: bg(e) });
    const out = [];
    const first = (sel) => document.querySelector(sel);
    for (const [what, sel] of [['relay', '#panel .relay'], ['lamp', '#panel .lamp:not(.signal-lamp)'],
                               ['signal lamp', '#panel .lamp.signal-lamp'], ['dial numeral', '#panel .dial .label'],
                               ['bank numeral', '#panel .bank .label'], ['column head', '#panel .scope h3']]) {
      const e = first(sel);
      const part = e.closest('.relay, .lamp') || e;
      const was = part.classList.contains('on');
      part.classList.remove('on');
      out.push(take(`${what} off`, e));
      part.classList.add('on');
      out.push(take(`${what} on`, e));
      part.classList.toggle('on', was);
    }
    const plain = [['explain', '#explain'], ['figcaption', '#cabinet figcaption'], ['machine figcaption', '#machine figcaption'],
                   ['hint', '#keypunch .hint'], ['invite', '.invite'], ['slider label', '.scrub'], ['summary th', '#summary th'],
                   ['summary td', '#run-state'], ['masthead', '.masthead .more summary'], ['More link', '.more-link'],
                   ['status', '#machine-status'], ['drawer summary', '#deck-drawer > summary'], ['generator label', '#gen-form label'],
                   ['footer', 'footer p'], ['error', '#deck-error'], ['button', '#play'], ['pressed button', '.speeds [aria-pressed="true"]'],
                   ['disabled button', 'button:disabled']];
    for (const [what, sel] of plain) { const e = first(sel); if (e) out.push(take(what, e)); }
    return out;
  });
  let worst = null;
  const low = [];
  for (const s of samples) {
    const layers = s.layers.map(parse);
    let base = layers[0];
    for (const l of layers.slice(1)) base = over(l, base);
    const ratio = contrast(over(parse(s.color), base), base);
    s.ratio = ratio;
    if (!worst || ratio < worst.ratio) worst = s;
    if (ratio < 4.5) low.push(`${s.what} ${ratio.toFixed(2)}:1 (${s.color} on ${s.layers.slice(-1)[0]})`);
  }
  console.log('contrast: ' + samples.map((s) => `${s.what} ${s.ratio.toFixed(1)}`).join(', '));
  console.log(`worst contrast: ${worst.what} ${worst.ratio.toFixed(2)}:1`);
  check(samples.length >= 28 && low.length === 0, 'WCAG AA contrast (4.5:1) for the panel\'s text on and off, buttons, captions, hints, labels',
        `${samples.length} texts, worst ${worst.what} ${worst.ratio.toFixed(2)}:1 ${low.join('; ')}`);

  // ---- prefers-reduced-motion
  const motion = async () => page.evaluate(() => {
    const on = (sel) => { const e = document.querySelector(sel); e.classList.add('on'); return e; };
    const parts = [on('#panel .relay'), on('#panel .lamp.signal-lamp'), on('#panel .lamp:not(.signal-lamp)')];
    const styles = [...parts, document.getElementById('play'), document.querySelector('.speeds button')].map((e) => getComputedStyle(e));
    const out = {
      flag: document.body.dataset.reducedMotion,
      glow: styles.slice(0, 3).map((s) => s.boxShadow),
      moving: styles.filter((s) => (s.transitionDuration.split(',').some((d) => parseFloat(d) > 0)) || s.animationName !== 'none').length,
    };
    for (const e of parts) e.classList.remove('on');
    return out;
  });
  const normal = await motion();
  await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
  // The flag follows the media query's change event, which comes with the next frame.
  await page.waitForFunction(() => document.body.dataset.reducedMotion === 'true', { timeout: 3000 }).catch(() => {});
  const reduced = await motion();
  console.log(`motion: normal glow ${normal.glow.join(' | ')}; reduced ${reduced.glow.join(' | ')}`);
  check(normal.flag === 'false' && normal.glow[0] !== 'none', 'without the preference the relays glow, the flag says false', JSON.stringify(normal));
  check(reduced.flag === 'true' && reduced.glow.every((g) => g === 'none') && reduced.moving === 0,
        'prefers-reduced-motion: no glow, no transition or animation, body[data-reduced-motion="true"]', JSON.stringify(reduced));
  await page.close();
  // Opened with the preference already set, the flag is set from the start.
  const again = await t.browser.newPage();
  await again.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
  await again.setViewport(t.SCREENS.laptop);
  await again.goto(`${t.server.url}/index.html`);
  const flag = await again.evaluate(() => document.body.dataset.reducedMotion);
  check(flag === 'true', 'a page opened under prefers-reduced-motion says so from the start', String(flag));
  await again.waitForSelector('body[data-settled="true"]', { timeout: 30000 });
  await again.close();
};
