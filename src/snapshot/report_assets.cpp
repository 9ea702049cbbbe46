#include "snapshot/report_assets.hpp"

// The HTML report's style and script, inline in every page so a report opens from a CI artifact
// without a server or network.

namespace sweep::snapshot {

const char* const kReportStyle = R"CSS(
:root{color-scheme:dark;--bg:#121418;--panel:#1a1d22;--panel2:#20242a;--line:#2c3139;--text:#dadee4;--muted:#8b929d;
--render:rgb(28,31,36);--accent:#8ab4f8;--fail:#f0565b;--error:#c77dff;--warning:#e9b44c;--new:#58a6ff;
--updated:#3cc4b4;--pass:#4cb86b;--mono:ui-monospace,"SF Mono",Menlo,Consolas,"DejaVu Sans Mono","Liberation Mono",monospace}
*{box-sizing:border-box}
html{background:var(--bg)}
body{margin:0;color:var(--text);font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"Noto Sans","DejaVu Sans",sans-serif}
code,.mono{font-family:var(--mono);font-size:12.5px}
a{color:inherit}
.s-fail{--c:var(--fail)}.s-error{--c:var(--error)}.s-warning{--c:var(--warning)}.s-new{--c:var(--new)}
.s-updated{--c:var(--updated)}.s-pass{--c:var(--pass)}.s-all{--c:var(--text)}
.top{position:sticky;top:0;z-index:3;background:rgba(18,20,24,.95);border-bottom:1px solid var(--line);padding:14px 24px 12px}
.top-row{display:flex;align-items:baseline;gap:14px;flex-wrap:wrap}
h1{font-size:19px;margin:0;font-weight:600;letter-spacing:.01em}
.verdict{font-weight:600;color:var(--c)}
.counts{margin:4px 0 2px;font-size:15px}
.meta{margin:0;color:var(--muted);font-size:12.5px;display:flex;flex-wrap:wrap;gap:4px 18px}
.meta code{color:var(--text)}
.bar{display:flex;align-items:center;gap:8px;flex-wrap:wrap;margin-top:10px}
.filters button,.flicker{font:inherit;font-size:12.5px;color:var(--text);background:var(--panel2);border:1px solid var(--line);
border-radius:6px;padding:4px 10px;cursor:pointer}
.filters button .n{display:inline-block;min-width:1.4em;margin-left:6px;padding:0 5px;border-radius:9px;text-align:center;
background:color-mix(in srgb,var(--c) 22%,transparent);color:var(--c);font-weight:600}
.filters button[aria-pressed=true],.flicker[aria-pressed=true]{border-color:var(--accent);background:#27303d}
.filters button:disabled{opacity:.4;cursor:default}
.keys{margin-left:auto;color:var(--muted);font-size:12px}
kbd{font:11px var(--mono);border:1px solid var(--line);border-bottom-width:2px;border-radius:4px;padding:0 4px;background:var(--panel2)}
main{padding:20px 24px 56px;max-width:1500px;margin:0 auto}
.empty{color:var(--muted)}
.case{background:var(--panel);border:1px solid var(--line);border-left:4px solid var(--c);border-radius:8px;padding:14px 18px 16px;
margin:0 0 18px;scroll-margin-top:150px}
.case.current{box-shadow:0 0 0 2px var(--accent)}
.case-head{display:flex;align-items:center;gap:10px;flex-wrap:wrap}
.badge{font:700 11px/1 var(--mono);letter-spacing:.05em;padding:4px 7px;border-radius:4px;color:#101215;background:var(--c)}
.case-name{font:600 16px/1.3 var(--mono);margin:0;word-break:break-all}
.case-name a{text-decoration:none}
.case-name a:hover{text-decoration:underline}
.case-time{margin-left:auto;color:var(--muted);font-size:12.5px}
.where{margin:4px 0 0;color:var(--muted);font-size:12.5px}
.where span+span::before{content:"\00b7";margin:0 7px;color:#5b616b}
.message{margin:10px 0 0;padding:8px 12px;background:var(--panel2);border-radius:6px;border-left:2px solid var(--c);
white-space:pre-wrap;word-break:break-word}
.case-body{display:flex;gap:22px;align-items:flex-start;margin-top:14px;flex-wrap:wrap}
.facts{flex:1 1 300px;min-width:0}
.facts h3{margin:0 0 6px;font-size:11.5px;font-weight:600;letter-spacing:.08em;text-transform:uppercase;color:var(--muted)}
.facts h3+*{margin-top:0}
.changes{list-style:none;margin:0 0 16px;padding:0}
.changes li{padding:5px 10px;border-radius:5px;margin-bottom:3px;color:var(--muted);word-break:break-word}
.changes li::before{content:"\2022";display:inline-block;width:1.1em;color:#5b616b}
.changes li.changed{color:var(--text);background:color-mix(in srgb,var(--c) 13%,transparent)}
.changes li.changed::before{content:"\25b8";color:var(--c)}
.numbers{display:grid;grid-template-columns:max-content 1fr;gap:5px 16px;margin:0}
.numbers dt{color:var(--muted)}
.numbers dd{margin:0;font-variant-numeric:tabular-nums}
.numbers .limit{color:var(--muted);margin-left:8px;font-size:12.5px}
.numbers .note{grid-column:1/-1;color:var(--warning);font-size:13px}
.compare{flex:0 1 auto;max-width:100%}
.stage{position:relative;max-width:100%;background:var(--render);box-shadow:0 0 0 1px var(--line);border-radius:4px;overflow:hidden;
container-type:inline-size;user-select:none}
.stage img{display:block;width:100%;height:100%}
.wipe-top{position:absolute;top:0;bottom:0;left:0;overflow:hidden}
.wipe-top img{width:100cqw;max-width:none}
.wipe-top::after{content:"";position:absolute;top:0;bottom:0;right:0;width:2px;background:rgba(255,255,255,.9);
box-shadow:0 0 3px rgba(0,0,0,.8)}
.tag,.stage.flickering::after{position:absolute;top:8px;font:600 11px/1 var(--mono);padding:4px 6px;border-radius:4px;
background:rgba(10,12,15,.72);color:#e8ebef;pointer-events:none}
.tag-left{left:8px}.tag-right{right:8px}
.stage.flickering .wipe-top{width:100%!important}
.stage.flickering .wipe-top::after,.stage.flickering .tag{display:none}
.stage.flickering[data-show=actual] .wipe-top{visibility:hidden}
.stage.flickering::after{content:attr(data-show);left:8px}
.controls{display:flex;align-items:center;gap:10px;margin-top:8px;color:var(--muted);font-size:12.5px}
.controls input{flex:1;accent-color:var(--accent)}
img{image-rendering:pixelated}
.trio{display:grid;gap:14px;margin-top:16px}
.trio figure{margin:0;min-width:0}
.trio a{display:block;background:var(--render);box-shadow:0 0 0 1px var(--line);border-radius:4px;overflow:hidden}
.trio img{display:block;width:100%;height:auto}
figcaption{margin-top:5px;color:var(--muted);font-size:12.5px;display:flex;gap:8px;align-items:baseline}
figcaption span{white-space:nowrap}
figcaption code{color:var(--text);overflow:hidden;text-overflow:ellipsis;white-space:nowrap}
.passes{background:var(--panel);border:1px solid var(--line);border-left:4px solid var(--pass);border-radius:8px;padding:12px 18px}
.passes summary{cursor:pointer;font-weight:600}
.passes summary .hint{color:var(--muted);font-weight:400;margin-left:8px;font-size:12.5px}
.pass-grid{list-style:none;margin:12px 0 2px;padding:0;display:grid;grid-template-columns:repeat(auto-fill,minmax(250px,1fr));
gap:2px 18px}
.pass-grid li{display:flex;gap:8px;padding:3px 0;border-bottom:1px solid #23272e;font:12.5px/1.4 var(--mono);min-width:0}
.pass-grid .pname{overflow:hidden;text-overflow:ellipsis;white-space:nowrap}
.pass-grid .pname::before{content:"\2713";color:var(--pass);margin-right:7px}
.pass-grid .ptime{margin-left:auto;color:var(--muted)}
[hidden]{display:none!important}
.legend{display:flex;flex-wrap:wrap;gap:4px 14px;margin:6px 0 0;padding:0;list-style:none;color:var(--muted);font-size:12.5px}
.legend li{display:flex;align-items:center;gap:6px}
.swatch{width:14px;height:14px;border-radius:3px;border:1px solid var(--line);display:inline-block}
.renderers{margin:6px 0 0;padding-left:18px;font-size:12.5px}
.renderers .this{color:var(--text)}
)CSS";

// The widgets (wipe slider, flicker), the filters, j/k, and the self-test a headless browser runs
// at #selftest: it counts the images that loaded, drives the first slider to both ends and the
// first flicker toggle, and writes what it found into body[data-selftest] and the title.
const char* const kReportScript = R"JS(
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
)JS";

}  // namespace sweep::snapshot
