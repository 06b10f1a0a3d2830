"""The page's inline CSS and script (report.html loads nothing from anywhere).

The script plays each card's crash on its canvas from the scene JSON beside it
(plan_picture.scene): lanes and lane lines, each body's corners every `step` seconds (the geometry
kernel's, interpolated between frames), moving at the plan's time until impact, where they stop for a
moment before the replay starts again. A slider scrubs; the button pauses; `#t=SECONDS` (or
`#t=impact`) in the address opens every animation paused at that moment. Each canvas records the
frames it drew in `data-drawn`, and any script error is counted on the body (`data-errors`), so a
test can read both from the page's DOM.
"""

STYLE = """
body{font:14px/1.4 system-ui,sans-serif;margin:0 auto;max-width:1080px;padding:0 16px 40px;
  color:#222;background:#fafafa}
header h1{margin:16px 0 4px;font-size:22px}
h2{font-size:18px;margin:24px 0 6px;border-bottom:1px solid #ddd;padding-bottom:4px}
h3{font-size:15px;margin:0}
.hint{color:#666;font-size:12px;margin:2px 0}
table{border-collapse:collapse;background:#fff}
th,td{border:1px solid #ddd;padding:4px 10px;text-align:left}
thead th{background:#f0f0f0}
tr.total th,tr.total td{font-weight:bold;background:#f7f7f7}
.pass{color:#137333}.fail{color:#b3261e}
.toc{margin:12px 0;font-size:13px}
.source,.meta,.crash{margin:2px 0;font-size:13px}
.crash{font-weight:600}
.provenance{font-size:12px;margin:4px 0 8px}
.provenance dl{display:grid;grid-template-columns:max-content 1fr;gap:2px 12px;margin:4px 0}
.provenance dt{color:#666}.provenance dd{margin:0;word-break:break-all}
.card{background:#fff;border:1px solid #ddd;border-radius:6px;padding:10px 12px;margin:10px 0}
.card.failed{border-color:#e6b3b0;background:#fff8f7}
.badges{margin:4px 0}
.badge{display:inline-block;border-radius:10px;padding:1px 9px;margin-right:6px;font-size:12px;
  text-decoration:none;border:1px solid}
.badge.pass{background:#e6f4ea;border-color:#137333}.badge.fail{background:#fce8e6;border-color:#b3261e}
.badge.none{color:#666;border-color:#bbb}
.views{display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}
.views>a{flex:1 1 100%}
.views img{border:1px solid #ddd;width:100%;height:auto}
.anim-note{flex:1;font-size:12px;color:#444;min-width:200px}
.anim{margin:0}
.anim canvas{border:1px solid #ddd;display:block;max-width:100%}
.anim figcaption{display:flex;gap:8px;align-items:center;font-size:12px;margin-top:4px}
.anim .scrub{flex:1}
.anim .clock{min-width:130px;font-variant-numeric:tabular-nums}
.files{font-size:12px;margin-top:6px}
.files ul{columns:2;margin:4px 0}
.error{color:#b3261e;font-size:13px}
code{font-size:12px;background:#f3f3f3;padding:0 3px;border-radius:3px}
"""

SCRIPT = """
(function () {
  "use strict";
  var errors = 0;
  window.addEventListener("error", function () {
    errors += 1;
    document.body.setAttribute("data-errors", String(errors));
  });
  var HOLD = 1.5; // s the bodies rest at impact before the replay starts again

  function Player(canvas) {
    var scene = JSON.parse(document.getElementById(canvas.getAttribute("data-scene")).textContent);
    var box = canvas.closest("figure");
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.scene = scene;
    this.play = box.querySelector(".play");
    this.scrub = box.querySelector(".scrub");
    this.clock = box.querySelector(".clock");
    this.time = 0;
    this.running = true;
    this.last = null;
    this.drawn = 0;
    this.visible = true;
    this.view = scene.view;
    this.scale = canvas.width / (2 * scene.view[2]);
    canvas.setAttribute("data-frames", String(scene.actors.length ? scene.actors[0].boxes.length : 0));
    var self = this;
    this.play.addEventListener("click", function () {
      self.running = !self.running;
      self.play.textContent = self.running ? "pause" : "play";
      self.last = null;
    });
    this.scrub.addEventListener("input", function () {
      self.running = false;
      self.play.textContent = "play";
      self.time = (Number(self.scrub.value) / 1000) * scene.impact.t;
      self.draw();
    });
  }

  Player.prototype.px = function (x, y) {
    var v = this.view;
    return [(x - v[0] + v[2]) * this.scale, (v[1] + v[2] - y) * this.scale];
  };

  Player.prototype.path = function (flat, close) {
    var ctx = this.ctx;
    ctx.beginPath();
    for (var i = 0; i + 1 < flat.length; i += 2) {
      var p = this.px(flat[i], flat[i + 1]);
      if (i === 0) ctx.moveTo(p[0], p[1]); else ctx.lineTo(p[0], p[1]);
    }
    if (close) ctx.closePath();
  };

  Player.prototype.corners = function (actor) {
    // the kernel's corners at the two frames around the time, blended
    var s = this.scene, n = actor.boxes.length;
    var f = Math.min(this.time / s.step, n - 1);
    var k = Math.min(Math.floor(f), n - 1), u = f - k;
    var a = actor.boxes[k], b = actor.boxes[Math.min(k + 1, n - 1)];
    var out = [];
    for (var i = 0; i < a.length; i++) out.push(a[i] + u * (b[i] - a[i]));
    return {corners: out, speed: actor.speeds[Math.round(f)]};
  };

  Player.prototype.follow = function () {
    // the camera frames the bodies and the impact point at this moment (never closer than 30 m
    // across), so that bodies far apart at the start and touching at impact both read well
    var s = this.scene, self = this;
    var xs = [s.impact.x], ys = [s.impact.y];
    s.actors.forEach(function (actor) {
      var q = self.corners(actor).corners;
      for (var i = 0; i + 1 < q.length; i += 2) { xs.push(q[i]); ys.push(q[i + 1]); }
    });
    var x0 = Math.min.apply(null, xs), x1 = Math.max.apply(null, xs);
    var y0 = Math.min.apply(null, ys), y1 = Math.max.apply(null, ys);
    var half = Math.max(x1 - x0, y1 - y0, 30) / 2 + 8;
    this.view = [(x0 + x1) / 2, (y0 + y1) / 2, half];
    this.scale = this.canvas.width / (2 * half);
  };

  Player.prototype.scaleBar = function () {
    var ctx = this.ctx, c = this.canvas;
    var metres = [5, 10, 20, 50, 100].filter(function (m) { return m * this.scale <= c.width / 4; }, this).pop() || 5;
    var w = metres * this.scale, x = c.width - w - 12, y = c.height - 14;
    ctx.fillStyle = "rgba(255,255,255,0.8)";
    ctx.fillRect(x - 6, y - 16, w + 12, 24);
    ctx.strokeStyle = "#111";
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(x, y); ctx.lineTo(x + w, y);
    ctx.stroke();
    ctx.fillStyle = "#111";
    ctx.font = "11px system-ui,sans-serif";
    ctx.fillText(metres + " m", x, y - 5);
    ctx.lineWidth = 1;
  };

  Player.prototype.draw = function () {
    var s = this.scene, ctx = this.ctx, c = this.canvas, self = this;
    this.follow();
    ctx.setLineDash([]);
    ctx.fillStyle = "#eef1e8";
    ctx.fillRect(0, 0, c.width, c.height);
    ctx.fillStyle = "#d6d6d6";
    s.walkways.forEach(function (w) { self.path(w, true); ctx.fill(); });
    ctx.fillStyle = "#9aa0a6";
    ctx.strokeStyle = "#9aa0a6";
    ctx.lineWidth = 0.5;
    s.asphalt.forEach(function (a) { self.path(a, true); ctx.fill(); ctx.stroke(); });
    ctx.fillStyle = "rgba(240,240,240,0.8)";
    s.crossings.forEach(function (w) { self.path(w, true); ctx.fill(); });
    ctx.lineWidth = 1;
    s.lines.forEach(function (l) {
      ctx.strokeStyle = l[0] === "centre" ? "#f2c200" : "#ffffff";
      ctx.setLineDash(l[0] === "divider" ? [6, 6] : []);
      self.path(l[1], false);
      ctx.stroke();
    });
    ctx.setLineDash([]);
    var hit = this.time >= s.impact.t - 1e-6;
    var ip = this.px(s.impact.x, s.impact.y);
    ctx.beginPath();
    ctx.arc(ip[0], ip[1], s.impact.r * this.scale, 0, 2 * Math.PI);
    ctx.fillStyle = hit ? "rgba(255,204,0,0.75)" : "rgba(255,204,0,0.3)";
    ctx.fill();
    var keys = [];
    s.actors.forEach(function (actor) {
      ctx.strokeStyle = actor.colour;
      ctx.globalAlpha = 0.5;
      ctx.lineWidth = 1;
      self.path(actor.path, false);
      ctx.stroke();
      ctx.globalAlpha = 1;
      var now = self.corners(actor), q = now.corners;
      self.path(q, true);
      ctx.fillStyle = actor.colour;
      ctx.fill();
      ctx.strokeStyle = "#000";
      ctx.stroke();
      // heading: from the centre to the front face's middle (corners 0 and 3), and past it
      var cx = (q[0] + q[2] + q[4] + q[6]) / 4, cy = (q[1] + q[3] + q[5] + q[7]) / 4;
      var fx = (q[0] + q[6]) / 2, fy = (q[1] + q[7]) / 2;
      var dx = fx - cx, dy = fy - cy, len = Math.hypot(dx, dy) || 1;
      var reach = len + 1.5;
      var a = self.px(cx, cy), b = self.px(cx + dx / len * reach, cy + dy / len * reach);
      ctx.beginPath();
      ctx.moveTo(a[0], a[1]);
      ctx.lineTo(b[0], b[1]);
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.lineWidth = 1;
      ctx.font = "bold 12px system-ui,sans-serif";
      // the name beside the body; role and speed in the key at the top left (labels of touching
      // bodies would cover each other)
      var tx = Math.min(Math.max(a[0] + 10, 4), c.width - 30);
      var ty = Math.min(Math.max(a[1] - 10, 14), c.height - 4);
      ctx.fillStyle = "rgba(255,255,255,0.75)";
      ctx.fillRect(tx - 2, ty - 12, ctx.measureText(actor.name).width + 4, 16);
      ctx.fillStyle = actor.colour;
      ctx.fillText(actor.name, tx, ty);
      keys.push([actor, now.speed]);
    });
    ctx.font = "12px system-ui,sans-serif";
    ctx.fillStyle = "rgba(255,255,255,0.85)";
    ctx.fillRect(6, 6, 190, 8 + 18 * keys.length);
    keys.forEach(function (k, i) {
      var actor = k[0], role = actor.label === "other" ? "" : " " + actor.label;
      ctx.fillStyle = actor.colour;
      ctx.fillRect(12, 12 + 18 * i, 12, 12);
      ctx.fillStyle = "#111";
      ctx.fillText(actor.name + role + ", " + Math.abs(k[1]).toFixed(0) + " km/h", 30, 22 + 18 * i);
    });
    if (hit) {
      ctx.strokeStyle = "#000";
      ctx.lineWidth = 3;
      ctx.beginPath();
      ctx.moveTo(ip[0] - 7, ip[1] - 7); ctx.lineTo(ip[0] + 7, ip[1] + 7);
      ctx.moveTo(ip[0] + 7, ip[1] - 7); ctx.lineTo(ip[0] - 7, ip[1] + 7);
      ctx.stroke();
      ctx.lineWidth = 1;
      ctx.fillStyle = "#b3261e";
      ctx.font = "bold 16px system-ui,sans-serif";
      ctx.fillText("IMPACT", c.width - 80, 24);
    }
    this.scaleBar();
    this.clock.textContent =
      "t = " + Math.min(this.time, s.impact.t).toFixed(1) + " s / impact " + s.impact.t.toFixed(1) + " s";
    this.scrub.value = String(Math.round(Math.min(this.time / (s.impact.t || 1), 1) * 1000));
    this.drawn += 1;
    c.setAttribute("data-drawn", String(this.drawn));
  };

  Player.prototype.tick = function (now) {
    if (this.running && this.visible) {
      if (this.last !== null) this.time += (now - this.last) / 1000;
      if (this.time > this.scene.impact.t + HOLD) this.time = 0;
      this.draw();
    }
    this.last = this.running ? now : null;
  };

  // only the canvases on screen play: a batch's page may hold hundreds
  // report.html#t=4.5 (or #t=impact) opens every animation paused at that moment
  var at = /[#&]t=([0-9.]+|impact)/.exec(window.location.hash);
  var players = [];
  var watch = "IntersectionObserver" in window ? new IntersectionObserver(function (entries) {
    entries.forEach(function (e) { e.target.player.visible = e.isIntersecting; });
  }) : null;
  document.querySelectorAll("canvas[data-scene]").forEach(function (canvas) {
    var p = new Player(canvas);
    canvas.player = p;
    if (at) {
      p.running = false;
      p.play.textContent = "play";
      p.time = at[1] === "impact" ? p.scene.impact.t : Math.min(Number(at[1]), p.scene.impact.t);
    }
    p.draw();
    players.push(p);
    if (watch) watch.observe(canvas);
  });
  function frame(now) {
    players.forEach(function (p) { p.tick(now); });
    window.requestAnimationFrame(frame);
  }
  if (players.length) window.requestAnimationFrame(frame);
  document.body.setAttribute("data-players", String(players.length));
})();
"""
