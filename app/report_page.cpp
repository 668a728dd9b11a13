#include "app/report_page.h"

#include "app/html_text.h"

namespace sedem::app {

namespace {

const char* kStyle = R"(
body { font: 15px/1.45 "DejaVu Sans", Verdana, sans-serif; color: #1b1f24; background: #fff;
  max-width: 1240px; margin: 0 auto; padding: 12px 24px 48px; }
h1 { font-size: 1.55em; margin: .3em 0 .3em; }
h2 { font-size: 1.2em; margin: 1.6em 0 .5em; padding-bottom: .2em; border-bottom: 1px solid #d0d7de; }
h3 { font-size: 1em; margin: 1em 0 .3em; }
nav a { margin-right: 1em; }
a { color: #0550ae; }
table { border-collapse: collapse; margin: .4em 0; }
th, td { text-align: left; padding: 3px 10px; border-bottom: 1px solid #e3e7eb; vertical-align: top; }
thead th { background: #f1f4f7; }
th.group { background: #f6f8fa; padding-top: 8px; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.status { display: inline-block; padding: 1px 10px; border-radius: 4px; font-weight: bold; }
.status.complete { background: #d8f3df; color: #0d5a22; }
.status.partial { background: #ffe1c2; color: #7a3000; }
.banner { border-left: 5px solid #d9480f; background: #fff3e6; padding: 8px 14px; margin: .8em 0; }
.note { color: #57606a; font-size: .93em; }
.warnings { border-left: 5px solid #bf8700; background: #fff8c5; padding: 6px 14px; margin: .8em 0; }
figure { margin: 1em 0 2.2em; }
figure img { max-width: 100%; height: auto; border: 1px solid #e3e7eb; }
figcaption { color: #57606a; font-size: .93em; margin-top: .3em; }
.player img { max-width: 100%; max-height: 640px; height: auto; border: 1px solid #e3e7eb; }
.controls { margin: .4em 0; display: flex; gap: .8em; align-items: center; }
.controls input { width: 320px; }
.strip { display: flex; gap: 6px; overflow-x: auto; padding-bottom: 6px; }
.strip img { height: 150px; width: auto; border: 1px solid #e3e7eb; }
ul.files { columns: 2; padding-left: 1.2em; }
.wide { overflow-x: auto; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: .92em; }
)";

// Plays the frames of each .player: a button and a slider over the names in data-frames.
const char* kScript = R"(
for (const p of document.querySelectorAll('.player')) {
  const frames = JSON.parse(p.dataset.frames);
  const img = p.querySelector('img'), range = p.querySelector('input');
  const button = p.querySelector('button'), label = p.querySelector('.frame-label');
  let timer = 0;
  const show = k => {
    range.value = k;
    img.src = frames[k];
    label.textContent = 'frame ' + (k + 1) + ' of ' + frames.length;
  };
  range.addEventListener('input', () => show(Number(range.value)));
  button.addEventListener('click', () => {
    if (timer) { clearInterval(timer); timer = 0; button.textContent = 'Play'; return; }
    timer = setInterval(() => show((Number(range.value) + 1) % frames.length), 200);
    button.textContent = 'Pause';
  });
}
)";

}  // namespace

std::string html_page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         html_escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n" + body +
         "<script>" + kScript + "</script>\n</body>\n</html>\n";
}

}  // namespace sedem::app
