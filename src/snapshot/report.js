(() => {
  'use strict';
  const wipe = (stage, value) => { stage.querySelector('.wipe-top').style.width = value + '%'; };
  const flicker = (compare, on) => {
    const stage = compare.querySelector('.stage');
    const button = compare.querySelector('.flicker');
    clearInterval(compare.flickerTimer);
    compare.flickerTimer = 0;
    stage.classList.toggle('flickering', on);
    stage.dataset.show = 'reference';
    button.setAttribute('aria-pressed', String(on));
    compare.querySelector('input.wipe').disabled = on;
    if (on) {
      compare.flickerTimer = setInterval(() => {
        stage.dataset.show = stage.dataset.show === 'reference' ? 'actual' : 'reference';
      }, 500);
    }
  };
  for (const compare of document.querySelectorAll('.compare')) {
    const slider = compare.querySelector('input.wipe');
    const stage = compare.querySelector('.stage');
    slider.addEventListener('input', () => wipe(stage, slider.value));
    wipe(stage, slider.value);
    compare.querySelector('.flicker').addEventListener('click', () => flicker(compare, !compare.flickerTimer));
  }

  const buttons = [...document.querySelectorAll('.filters button')];
  const passes = document.querySelector('.passes');
  const show = (status) => {
    for (const b of buttons) b.setAttribute('aria-pressed', String(b.dataset.filter === status));
    for (const el of document.querySelectorAll('[data-status]')) {
      el.hidden = status !== 'all' && el.dataset.status !== status;
    }
    if (passes) {
      passes.hidden = status !== 'all' && status !== 'pass';
      if (status === 'pass') passes.open = true;
    }
  };
  for (const b of buttons) b.addEventListener('click', () => show(b.dataset.filter));

  let current = null;
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const cards = [...document.querySelectorAll('.case.attention')].filter((c) => !c.hidden);
    if ((e.key === 'j' || e.key === 'k') && cards.length) {
      const at = cards.indexOf(current);
      const next = e.key === 'j' ? Math.min(at + 1, cards.length - 1) : Math.max(at < 0 ? 0 : at - 1, 0);
      if (current) current.classList.remove('current');
      current = cards[next];
      current.classList.add('current');
      current.scrollIntoView({block: 'start'});
    } else if (e.key === 'f' && current) {
      const compare = current.querySelector('.compare');
      if (compare) flicker(compare, !compare.flickerTimer);
    }
  });

  const selftest = () => {
    const images = [...document.images];
    const loaded = images.filter((img) => img.complete && img.naturalWidth > 0).length;
    const found = ['images ' + loaded + '/' + images.length + ' loaded'];
    const compare = document.querySelector('.compare');
    const finish = () => {
      const result = found.join('; ');
      document.body.dataset.selftest = result;
      document.title = result;
    };
    if (!compare) {
      found.push('no slider');
      finish();
      return;
    }
    const slider = compare.querySelector('input.wipe');
    const stage = compare.querySelector('.stage');
    const top = compare.querySelector('.wipe-top');
    const shown = (value) => {
      slider.value = String(value);
      slider.dispatchEvent(new Event('input'));
      return top.getBoundingClientRect().width;
    };
    const full = stage.clientWidth;
    const atZero = shown(0);
    const atHundred = shown(100);
    const topImage = top.querySelector('img').getBoundingClientRect().width;
    shown(50);
    const sliderOk = full > 0 && atZero < 1 && Math.abs(atHundred - full) < 1.5 && Math.abs(topImage - full) < 1.5;
    found.push(sliderOk ? 'slider ok'
                        : 'slider failed (0: ' + atZero + ' px, 100: ' + atHundred + ' px, image ' + topImage +
                              ' px of ' + full + ' px)');
    compare.querySelector('.flicker').click();
    const first = getComputedStyle(top).visibility;
    setTimeout(() => {
      const second = getComputedStyle(top).visibility;
      compare.querySelector('.flicker').click();
      found.push(first === 'visible' && second === 'hidden' ? 'flicker ok'
                                                            : 'flicker failed (' + first + ', then ' + second + ')');
      finish();
    }, 600);
  };
  if (location.hash === '#selftest') {
    if (document.readyState === 'complete') selftest();
    else window.addEventListener('load', selftest);
  }
})();
