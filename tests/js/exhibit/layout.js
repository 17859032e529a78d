// Issue 31, item 1: a first view that invites (docs/web.md). On a 1366x768 laptop the machine
// from above, the cabinet and the controls are seen at once with Play, without scrolling, the
// keypunch in its closed drawer and one sentence saying what to do; on a 390x844 phone one
// column that never scrolls sideways, the state cell inside the screen, every panel part and
// button a touch target of 24 x 24 CSS px at least (WCAG 2.5.8). Real geometry, measured.
'use strict';

module.exports = async function layout(t) {
  const { check } = t;

  // ---- the laptop
  const laptop = await t.open('laptop');
  await laptop.waitForFunction(() => !document.getElementById('play').disabled);
  const view = await laptop.evaluate(() => {
    const box = (sel) => {
      const r = document.querySelector(sel).getBoundingClientRect();
      return { sel, left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height };
    };
    return {
      w: window.innerWidth, h: window.innerHeight, scrollY: window.scrollY,
      scrollWidth: document.scrollingElement.scrollWidth,
      boxes: ['#play', '.controls', '#from-above', '#panel', '#scrub', '#summary'].map(box),
      drawerOpen: document.getElementById('deck-drawer').open,
      listingShown: document.getElementById('listing').checkVisibility(),
      invite: document.querySelector('.invite').textContent.replace(/\s+/g, ' ').trim(),
      parts: document.querySelectorAll('#panel .relay, #panel .dial, #panel .lamp').length,
    };
  });
  for (const b of view.boxes) {
    console.log(`laptop ${b.sel}: ${b.width.toFixed(0)}x${b.height.toFixed(0)} at (${b.left.toFixed(0)}, ${b.top.toFixed(0)})`);
    check(b.width > 0 && b.height > 0 && b.left >= 0 && b.top >= 0 && b.right <= view.w && b.bottom <= view.h,
          `1366x768: ${b.sel} wholly in the first view, no scrolling`,
          `${b.left.toFixed(0)},${b.top.toFixed(0)} – ${b.right.toFixed(0)},${b.bottom.toFixed(0)} in ${view.w}x${view.h}`);
  }
  check(view.scrollY === 0 && view.scrollWidth <= view.w, '1366x768: the page starts at the top, nothing sideways');
  check(view.parts > 500, '1366x768: the cabinet in view is the whole cabinet', `${view.parts} parts`);
  check(!view.drawerOpen && !view.listingShown, '1366x768: the keypunch (listing, fields, cards) waits in its closed drawer');
  check(/Play/.test(view.invite) && /tour/.test(view.invite), 'one sentence says what to do', view.invite);
  const masthead = await laptop.$eval('.masthead', (e) => e.getBoundingClientRect().height);
  check(masthead <= 80, '1366x768: the masthead is short (its paragraph behind "More")', `${masthead.toFixed(0)} px`);
  await t.shot(laptop, 'first-view-laptop');
  // With a tour caption of six lines above it (web/tour.js fills #tour), the cabinet stays in view.
  const withCaption = await laptop.evaluate(() => {
    const tour = document.getElementById('tour');
    const was = [tour.hidden, tour.innerHTML];
    tour.hidden = false;
    tour.innerHTML = '<p>' + Array(6).fill('A caption line of the tour, in plain words.').join('<br>') + '</p>';
    const p = document.getElementById('panel').getBoundingClientRect();
    const c = tour.getBoundingClientRect();
    [tour.hidden, tour.innerHTML] = was;
    return { panelBottom: Math.round(p.bottom), captionBottom: Math.round(c.bottom), captionTop: Math.round(c.top), h: innerHeight };
  });
  check(withCaption.panelBottom <= withCaption.h && withCaption.captionTop > 0 && withCaption.captionBottom <= withCaption.h,
        '1366x768: a six-line tour caption and the cabinet in view together', JSON.stringify(withCaption));
  // At the end the state cell says "completed" and the time is long: still inside, clear of the cabinet.
  await laptop.click('#to-end');
  await laptop.waitForSelector('#run-state[data-finished="true"]');
  const endView = await laptop.evaluate(() => {
    const s = document.getElementById('run-state').getBoundingClientRect();
    const p = document.getElementById('panel').getBoundingClientRect();
    const overlap = !(s.right <= p.left || s.left >= p.right || s.bottom <= p.top || s.top >= p.bottom);
    return { s: [s.left, s.top, s.right, s.bottom].map(Math.round), overlap, w: innerWidth, h: innerHeight,
             panelBottom: p.bottom, text: document.getElementById('run-state').textContent };
  });
  check(!endView.overlap && endView.s[2] <= endView.w && endView.s[3] <= endView.h && endView.panelBottom <= endView.h,
        '1366x768 at the end: the state cell in view, clear of the cabinet, the cabinet still in view', JSON.stringify(endView));
  await t.shot(laptop, 'end-view-laptop');
  // A deck error does not hide in the closed drawer: the drawer opens to show it.
  const bad = await laptop.evaluate(() => {
    const l = document.getElementById('listing');
    const good = l.value;
    l.value = good.replace('1,0,table,+,1,8.785', '1,0,table,+,7,8.785');
    l.dispatchEvent(new Event('input'));
    return good;
  });
  await laptop.waitForFunction(() => !document.getElementById('deck-error').hidden, { timeout: 10000 }).catch(() => {});
  const errorShown = await laptop.evaluate(() => document.getElementById('deck-drawer').open &&
                                           document.getElementById('deck-error').checkVisibility());
  check(errorShown, 'a deck error opens the drawer: it is seen, not hidden in the closed drawer');
  await laptop.evaluate((good) => {
    const l = document.getElementById('listing');
    l.value = good;
    l.dispatchEvent(new Event('input'));
    document.getElementById('deck-drawer').open = false;
  }, bad);
  await laptop.waitForFunction(() => document.getElementById('deck-error').hidden);
  // The drawer opens on its summary, and the keypunch is there.
  await laptop.click('#deck-drawer > summary');
  const opened = await laptop.$eval('#listing', (e) => e.getBoundingClientRect().height > 50 && e.value.length > 100);
  check(opened, 'the drawer opens on a click and shows the listing');
  await t.shot(laptop, 'first-view-laptop-drawer', true);
  await laptop.close();

  // ---- the phone
  const phone = await t.open('phone');
  await phone.waitForFunction(() => !document.getElementById('play').disabled);
  await t.shot(phone, 'first-view-phone');
  await t.shot(phone, 'first-view-phone-full', true);
  // The longest state text the run shows: at its end.
  await phone.click('#to-end');
  await phone.waitForSelector('#run-state[data-finished="true"]');
  const p = await phone.evaluate(() => {
    const w = window.innerWidth;
    const wide = [...document.querySelectorAll('body *')].filter((e) => e.checkVisibility() &&
      (e.getBoundingClientRect().right > w + 0.5 || e.getBoundingClientRect().left < -0.5));
    const state = document.getElementById('run-state').getBoundingClientRect();
    const targets = [...document.querySelectorAll('#panel .relay, #panel .dial, #panel .lamp, button, input, summary')]
      .filter((e) => e.checkVisibility());
    const small = targets.filter((e) => { const r = e.getBoundingClientRect(); return r.width < 24 || r.height < 24; });
    const controlsTop = document.querySelector('.controls').getBoundingClientRect().top;
    const machineTop = document.getElementById('machine').getBoundingClientRect().top;
    const panelTop = document.getElementById('panel').getBoundingClientRect().top;
    return {
      w, scrollWidth: document.scrollingElement.scrollWidth, wide: wide.slice(0, 5).map((e) => e.tagName + '#' + e.id + '.' + e.className),
      state: [state.left, state.right], targets: targets.length,
      small: small.slice(0, 5).map((e) => `${e.tagName}.${e.className} ${e.getBoundingClientRect().width.toFixed(0)}x${e.getBoundingClientRect().height.toFixed(0)}`),
      smallCount: small.length, controlsFirst: controlsTop < machineTop && controlsTop < panelTop,
      play: document.getElementById('play').getBoundingClientRect().bottom,
    };
  });
  console.log(`phone: page ${p.scrollWidth} px wide in ${p.w}; ${p.targets} targets, ${p.smallCount} smaller than 24x24 ${p.small.join(', ')}`);
  check(p.scrollWidth <= 390 && p.wide.length === 0, '390x844: nothing wider than the screen, no sideways scrolling',
        `${p.scrollWidth} px; ${p.wide.join(', ')}`);
  check(p.state[0] >= 0 && p.state[1] <= p.w, '390x844: the state cell is inside the screen', p.state.map((x) => x.toFixed(0)).join('–'));
  check(p.targets > 500 && p.smallCount === 0, '390x844: every panel part and control is at least 24x24 CSS px',
        `${p.smallCount} of ${p.targets} smaller`);
  check(p.controlsFirst && p.play <= 844, '390x844: the controls come first, Play in the first screen', `Play ends at ${p.play.toFixed(0)}`);
  await t.shot(phone, 'end-view-phone');
  // The drawer open, field by field: still nothing wider than the phone.
  await phone.click('#deck-drawer > summary');
  await phone.click('#tab-fields');
  await phone.waitForFunction(() => document.querySelectorAll('#fields input').length > 10);
  const drawerWidth = await phone.evaluate(() => document.scrollingElement.scrollWidth);
  check(drawerWidth <= 390, '390x844, the drawer open field by field: no sideways scrolling of the page', `${drawerWidth} px`);
  await t.shot(phone, 'drawer-phone');
  await phone.close();
};
