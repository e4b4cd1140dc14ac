// SPDX-License-Identifier: MIT
// The VROC replay viewer (docs/viewer.md). Reads the "vroc-view/1" data embedded in the page
// (tools/viewer/src/page_payload.h), builds every body's geometry once, and draws each view's runs
// with three.js r111 (Debian's libjs-three, inlined before this script). Z is up, as in the scenes.
// window.vrocViewer exposes the self-test and the helpers the tests use (tests/tools/viewer/).
(function () {
  'use strict';

  var GHOST_OPACITY = 0.6;      // overlay mode: every view's main run, translucent
  var MEMBER_OPACITY = 0.14;    // ensemble members around the median
  var EVENT_LIFE_S = 0.12;      // [s] a contact marker stays this long after its event
  var MAX_MARKERS = 48;         // per run

  var timing = { script_start_ms: performance.now() };
  var data = JSON.parse(document.getElementById('vroc-data').textContent);
  timing.parsed_ms = performance.now();
  var state = { frame: 0, playing: false, speed: 1, simTime: 0, overlay: false, colour: 'body', reference: 0,
                events: true, penetration: true, members: true, lastWall: 0 };
  var three = {};               // renderer, scene, camera, controls, lights
  var runs = [];                // per data.runs entry: {data, view, poses, flags, events, group, bodies: [{object, materials}], markers}
  var views = [];               // [{key, label, tint, main: run index, members: [run indices]}]
  var viewOfRun = [];           // data.runs index -> views index
  var staticGroup = null;

  // ---- decoding -------------------------------------------------------------------------------
  function bytesOf(base64) {
    var text = atob(base64);
    var out = new Uint8Array(text.length);
    for (var i = 0; i < text.length; ++i) out[i] = text.charCodeAt(i);
    return out;
  }
  // Little-endian Float32 whatever the host: a view of the bytes on a little-endian host (all
  // common ones), DataView (which states the byte order) elsewhere.
  var littleEndianHost = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;
  function float32sOf(base64) {
    var bytes = bytesOf(base64), n = bytes.length >> 2;
    if (littleEndianHost) return new Float32Array(bytes.buffer, 0, n);
    var out = new Float32Array(n), view = new DataView(bytes.buffer);
    for (var i = 0; i < n; ++i) out[i] = view.getFloat32(4 * i, true);
    return out;
  }
  // The one place quaternion order is handled. Files and the data hold [x, y, z, w]; the packed
  // poses keep x, y, z with w >= 0 (q and -q are one rotation) and w is restored here.
  // THREE.Quaternion takes (x, y, z, w) as well.
  function quatFromPacked(a, o) {
    var x = a[o], y = a[o + 1], z = a[o + 2];
    return new THREE.Quaternion(x, y, z, Math.sqrt(Math.max(0, 1 - x * x - y * y - z * z)));
  }
  function quatFromPose(p) { return new THREE.Quaternion(p[3], p[4], p[5], p[6]); }   // [x y z qx qy qz qw]

  // ---- geometry, once per body part -----------------------------------------------------------
  function hullGeometry(part) {
    var v = part.vertices, positions = [];
    part.faces.forEach(function (face) {
      for (var i = 1; i + 1 < face.length; ++i)
        [face[0], face[i], face[i + 1]].forEach(function (k) { positions.push(v[3 * k], v[3 * k + 1], v[3 * k + 2]); });
    });
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    g.computeVertexNormals();   // not indexed: flat faces
    return g;
  }
  function partGeometry(part) {
    if (part.type === 'sphere') return new THREE.SphereBufferGeometry(part.radius, 24, 16);
    if (part.type === 'box') {
      var h = part.half_extents;
      return new THREE.BoxBufferGeometry(2 * h[0], 2 * h[1], 2 * h[2]);
    }
    return hullGeometry(part);
  }
  function placePart(object, part) {
    object.position.set(part.pose[0], part.pose[1], part.pose[2]);
    object.quaternion.copy(quatFromPose(part.pose));
    return object;
  }
  var geometries = data.bodies.map(function (body) {
    return body.parts.map(function (part) {
      var g = partGeometry(part);
      return { mesh: g, edges: new THREE.EdgesGeometry(g, part.type === 'sphere' ? 1 : 10) };
    });
  });

  // ---- colours --------------------------------------------------------------------------------
  function bodyColour(k) { return new THREE.Color().setHSL(((k * 137.508) % 360) / 360, 0.7, 0.5); }
  // Ghosts: every engine's runs overlaid in one view, each engine in its tint (data.runs[r].tint,
  // tools/viewer/src/engine_tints.h: Okabe-Ito, in the recording's order), as its label and legend
  // entry show it. Colour by distance keeps the distance colours; the labels still carry the tints.
  function ghosts() { return state.overlay && views.length > 1; }
  // Distance [m] -> blue (<= collision distance) ... red (>= 1 m), on a log scale.
  function distanceColour(d) {
    var lo = Math.log10(Math.max(1e-9, data.collision_distance)), hi = 0;
    var t = (Math.log10(Math.max(d, 1e-12)) - lo) / (hi - lo);
    t = Math.min(1, Math.max(0, t));
    return new THREE.Color().setHSL(0.66 * (1 - t), 0.85, 0.5);
  }

  // ---- building the scene ---------------------------------------------------------------------
  function bodyObject(b, opacity, colour) {
    var body = data.bodies[b], group = new THREE.Group(), materials = [];
    body.parts.forEach(function (part, p) {
      var geo = geometries[b][p];
      if (body.kind === 'real') {   // the paper draws the real world as wireframe
        group.add(placePart(new THREE.LineSegments(geo.edges, new THREE.LineBasicMaterial({ color: 0x3a3a3a })), part));
        return;
      }
      var m = new THREE.MeshLambertMaterial({ color: colour, transparent: opacity < 1, opacity: opacity,
                                              depthWrite: opacity >= 1 });
      if (body.kind === 'tracked') m.opacity = Math.min(opacity, 0.35), m.transparent = true, m.depthWrite = false;
      materials.push(m);
      group.add(placePart(new THREE.Mesh(geo.mesh, m), part));
      if (body.kind === 'tracked')   // tracked: marked by orange edges
        group.add(placePart(new THREE.LineSegments(geo.edges, new THREE.LineBasicMaterial({ color: 0xff7a00 })), part));
    });
    return { object: group, materials: materials };
  }
  function buildRun(r) {
    var d = data.runs[r];
    var run = { data: d, view: viewOfRun[r], poses: float32sOf(d.poses), flags: d.has_penetration ? bytesOf(d.penetrating) : null,
                events: float32sOf(d.events), group: new THREE.Group(), bodies: [], markers: [] };
    var opacity = d.median ? 1 : MEMBER_OPACITY;
    data.bodies.forEach(function (body, b) {
      if (body.moving_index < 0) return;
      var o = bodyObject(b, opacity, bodyColour(body.moving_index));
      o.index = b;
      o.baseOpacity = opacity;
      run.bodies[body.moving_index] = o;
      run.group.add(o.object);
    });
    var markerGeometry = new THREE.SphereBufferGeometry(1, 8, 6);
    for (var i = 0; i < (d.median ? MAX_MARKERS : 0); ++i) {
      var marker = new THREE.Mesh(markerGeometry, new THREE.MeshBasicMaterial({ color: 0xffd000, transparent: true, depthTest: false }));
      marker.visible = false;
      marker.renderOrder = 10;
      run.markers.push(marker);
      run.group.add(marker);
    }
    three.scene.add(run.group);
    return run;
  }
  function buildStatic() {
    staticGroup = new THREE.Group();
    data.bodies.forEach(function (body, b) {
      if (body.moving_index >= 0) return;
      var o = bodyObject(b, 1, 0x888888).object;
      o.position.set(body.pose[0], body.pose[1], body.pose[2]);
      o.quaternion.copy(quatFromPose(body.pose));
      staticGroup.add(o);
    });
    three.scene.add(staticGroup);
  }
  function buildViews() {
    var byKey = {};
    data.runs.forEach(function (d, r) {
      var key = d.member < 0 ? 'run:' + d.label : 'ensemble:' + d.backend;
      if (!(key in byKey)) {
        byKey[key] = views.length;
        views.push({ key: key, label: d.member < 0 ? d.label : d.backend + ' (ensemble)', tint: d.tint, main: -1, members: [] });
      }
      viewOfRun[r] = byKey[key];
      var v = views[byKey[key]];
      if (d.median && v.main < 0) v.main = r; else v.members.push(r);
    });
    views.forEach(function (v) { if (v.main < 0) v.main = v.members.shift(); });
  }

  // ---- the state at a frame ---------------------------------------------------------------------
  function poseAt(run, frame, k) {
    var o = (frame * data.moving_bodies + k) * 6, a = run.poses;
    return { position: new THREE.Vector3(a[o], a[o + 1], a[o + 2]), quaternion: quatFromPacked(a, o + 3) };
  }
  function penetrating(run, frame, k) {
    if (!run.flags) return false;
    var bit = frame * data.moving_bodies + k;
    return (run.flags[bit >> 3] >> (bit & 7) & 1) === 1;
  }
  function referenceRun() { return runs[views[state.reference].main]; }
  // The colour a body shows (before lighting): its own, its engine's tint as a ghost, or its
  // distance from the reference run's same body (the per-body term of the reports' divergence,
  // harness::maxPositionError).
  function displayColour(run, frame, k) {
    if (state.colour === 'distance')
      return distanceColour(poseAt(run, frame, k).position.distanceTo(poseAt(referenceRun(), frame, k).position));
    return ghosts() ? new THREE.Color(views[run.view].tint) : bodyColour(k);
  }
  function updateRun(run, frame, opacity) {
    run.bodies.forEach(function (o, k) {
      if (!o) return;
      var p = poseAt(run, frame, k);
      o.object.position.copy(p.position);
      o.object.quaternion.copy(p.quaternion);
      var colour = displayColour(run, frame, k), hot = state.penetration && penetrating(run, frame, k);
      o.materials.forEach(function (m) {
        m.color.copy(colour);
        m.emissive.setHex(hot ? 0xff0000 : 0x000000);
        if (data.bodies[o.index].kind === 'virtual') {
          m.opacity = opacity;
          m.transparent = opacity < 1;
          m.depthWrite = opacity >= 1;
        }
      });
    });
    updateMarkers(run, data.times[frame]);
  }
  function updateMarkers(run, t) {
    var e = run.events, n = e.length / 6, used = 0, size = 0.25 * typicalRadius;
    // events are in time order: find the first within EVENT_LIFE_S before t
    var lo = 0, hi = n;
    while (lo < hi) { var mid = (lo + hi) >> 1; if (e[6 * mid] < t - EVENT_LIFE_S) lo = mid + 1; else hi = mid; }
    for (var i = lo; state.events && i < n && e[6 * i] <= t + 1e-9 && used < run.markers.length; ++i, ++used) {
      var m = run.markers[used], age = (t - e[6 * i]) / EVENT_LIFE_S;
      m.position.set(e[6 * i + 3], e[6 * i + 4], e[6 * i + 5]);
      m.scale.setScalar(size * (1 + age));
      m.material.opacity = 0.9 * (1 - 0.7 * age);
      m.visible = true;
    }
    for (; used < run.markers.length; ++used) run.markers[used].visible = false;
  }

  // ---- camera and layout ------------------------------------------------------------------------
  var typicalRadius = 0.05;
  // Frames the moving bodies: every body at the start, and the middle 60 % of their sampled
  // positions over the run per axis (so a body falling off the world does not shrink the rest).
  function fitCamera() {
    var box = new THREE.Box3(), radii = [], xs = [[], [], []];
    runs.forEach(function (run) {
      if (!run.data.median) return;
      for (var f = 0; f < data.times.length; f += Math.max(1, Math.floor(data.times.length / 50)))
        for (var k = 0; k < data.moving_bodies; ++k) {
          var p = poseAt(run, f, k).position;
          xs[0].push(p.x), xs[1].push(p.y), xs[2].push(p.z);
          if (f === 0) box.expandByPoint(p);
        }
    });
    if (xs[0].length) {
      var lo = [], hi = [];
      xs.forEach(function (v, i) {
        v.sort(function (a, b) { return a - b; });
        lo[i] = v[Math.floor(0.2 * (v.length - 1))];
        hi[i] = v[Math.ceil(0.8 * (v.length - 1))];
      });
      box.expandByPoint(new THREE.Vector3(lo[0], lo[1], lo[2])).expandByPoint(new THREE.Vector3(hi[0], hi[1], hi[2]));
    }
    data.bodies.forEach(function (body) {
      if (body.moving_index < 0) return;
      var s = new THREE.Box3().setFromObject(runs[0].bodies[body.moving_index].object).getBoundingSphere(new THREE.Sphere());
      radii.push(s.radius);
    });
    if (radii.length) { radii.sort(function (a, b) { return a - b; }); typicalRadius = radii[radii.length >> 1]; }
    if (box.isEmpty()) box.setFromObject(staticGroup);
    box.expandByScalar(2 * typicalRadius);
    var sphere = box.getBoundingSphere(new THREE.Sphere());
    var radius = Math.max(sphere.radius, 0.05);
    var distance = radius / Math.sin(THREE.Math.degToRad(three.camera.fov / 2)) * 1.05;
    var dir = new THREE.Vector3(0.35, -1, 0.55).normalize();
    three.camera.position.copy(sphere.center).addScaledVector(dir, distance);
    three.camera.near = distance / 100;
    three.camera.far = distance * 100;
    three.controls.target.copy(sphere.center);
    three.camera.lookAt(sphere.center);
    three.camera.updateProjectionMatrix();
    three.controls.update();
  }
  // The views' rectangles [CSS px] in the stage (the area below the control bar); `windowSize`
  // [w, h] lays them out for another window size than the current one (the tests' screenshots).
  function layout(windowSize) {
    var n = state.overlay ? 1 : views.length;
    var cols = Math.ceil(Math.sqrt(n)), rows = Math.ceil(n / cols);
    var stage = document.getElementById('vroc-stage').getBoundingClientRect();
    var W = windowSize ? windowSize[0] - stage.left : stage.width, H = windowSize ? windowSize[1] - stage.top : stage.height;
    var w = Math.floor(W / cols), h = Math.floor(H / rows);
    var rects = [];
    for (var i = 0; i < n; ++i) rects.push({ x: (i % cols) * w, y: Math.floor(i / cols) * h, w: w, h: h });
    return { rects: rects, width: Math.floor(W), height: Math.floor(H), left: stage.left, top: stage.top };
  }

  // ---- drawing ---------------------------------------------------------------------------------
  function showOnly(visibleRuns) {
    runs.forEach(function (run, r) { run.group.visible = visibleRuns.indexOf(r) >= 0; });
  }
  function runsOfView(v) {
    return [v.main].concat(state.members ? v.members : []);
  }
  function render() {
    var L = layout(), renderer = three.renderer;
    var size = renderer.getSize(new THREE.Vector2());
    if (size.x !== L.width || size.y !== L.height) renderer.setSize(L.width, L.height, false);   // a resize clears
    renderer.setScissorTest(true);
    renderer.setClearColor(0xf7f7f4);
    var labels = document.getElementById('vroc-labels');
    labels.innerHTML = '';
    L.rects.forEach(function (rect, i) {
      var shown = state.overlay ? views.reduce(function (all, v) { return all.concat(runsOfView(v)); }, []) : runsOfView(views[i]);
      shown.forEach(function (r) {
        var d = runs[r].data;
        updateRun(runs[r], state.frame, !d.median ? MEMBER_OPACITY : state.overlay && views.length > 1 ? GHOST_OPACITY : 1);
      });
      showOnly(shown);
      var y = L.height - rect.y - rect.h;   // WebGL's viewport origin is the bottom left
      renderer.setViewport(rect.x, y, rect.w, rect.h);
      renderer.setScissor(rect.x, y, rect.w, rect.h);
      renderer.clear();
      three.camera.aspect = rect.w / rect.h;
      three.camera.updateProjectionMatrix();
      renderer.render(three.scene, three.camera);
      var label = document.createElement('div');
      if (state.overlay) {
        label.appendChild(document.createTextNode('overlay: '));
        views.forEach(function (v) { label.appendChild(engineEntry(v)); });
      } else {
        label.appendChild(engineEntry(views[i]));
      }
      label.style.left = rect.x + 4 + 'px';
      label.style.top = rect.y + 4 + 'px';
      labels.appendChild(label);
    });
    document.getElementById('vroc-time').textContent =
        't = ' + data.times[state.frame].toFixed(3) + ' s (frame ' + state.frame + ' / ' + (data.times.length - 1) + ')';
    document.getElementById('vroc-slider').value = state.frame;
  }

  // ---- time -----------------------------------------------------------------------------------
  function setFrame(f) {
    state.frame = Math.max(0, Math.min(data.times.length - 1, Math.round(f)));
    state.simTime = data.times[state.frame];
    render();
    return state.frame;
  }
  function frameAtTime(t) {
    var f = 0;
    while (f + 1 < data.times.length && data.times[f + 1] <= t + 1e-12) ++f;
    return f;
  }
  function tick(wall) {
    if (!state.playing) return;
    var dt = state.lastWall ? (wall - state.lastWall) / 1000 : 0;
    state.lastWall = wall;
    state.simTime += dt * state.speed;
    if (state.simTime > data.times[data.times.length - 1]) state.simTime = data.times[0];
    state.frame = frameAtTime(state.simTime);
    render();
    requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    state.playing = on;
    state.lastWall = 0;
    document.getElementById('vroc-play').textContent = on ? 'pause' : 'play';
    if (on) requestAnimationFrame(tick);
  }

  // ---- the self-test and the tests' helpers -------------------------------------------------------
  // Where body b's origin (its centre for a sphere) lands [CSS px from the window's top left] in
  // view v at `frame`, through the page's own camera; `windowSize` as for layout().
  function project(b, v, frame, windowSize) {
    var body = data.bodies[b], L = layout(windowSize), rect = L.rects[state.overlay ? 0 : v];
    var run = runs[views[v].main], f = frame === undefined ? state.frame : frame;
    var p = body.moving_index >= 0 ? poseAt(run, f, body.moving_index).position : new THREE.Vector3(body.pose[0], body.pose[1], body.pose[2]);
    three.camera.aspect = rect.w / rect.h;
    three.camera.updateProjectionMatrix();
    var ndc = p.clone().project(three.camera);
    return { x: L.left + rect.x + (ndc.x + 1) / 2 * rect.w, y: L.top + rect.y + (1 - ndc.y) / 2 * rect.h };
  }
  function colourOf(b, v, frame) {
    var body = data.bodies[b];
    if (body.moving_index < 0) return '#3a3a3a';
    return '#' + displayColour(runs[views[v].main], frame === undefined ? state.frame : frame, body.moving_index).getHexString();
  }
  function hashParams() {
    var out = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
      var i = kv.indexOf('=');
      if (i > 0) out[decodeURIComponent(kv.slice(0, i))] = decodeURIComponent(kv.slice(i + 1));
    });
    return out;
  }
  // The engines' entries of an element (legend or labels) as drawn: name and swatch colour.
  function drawnEntries(id) {
    return Array.prototype.map.call(document.querySelectorAll('#' + id + ' .vroc-engine'), function (e) {
      var rgb = getComputedStyle(e.querySelector('.vroc-swatch')).backgroundColor.match(/\d+/g).map(Number);
      return { label: e.textContent, tint: '#' + new THREE.Color(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255).getHexString() };
    });
  }
  // The 3 x 3 pixels drawn around (x, y) [CSS px from the window's top left] as "#rrggbb", read
  // back from the canvas (its drawing buffer is kept: preserveDrawingBuffer), rows top to bottom.
  function drawnPixels(x, y) {
    var gl = three.renderer.getContext(), ratio = three.renderer.getPixelRatio(), L = layout(), rgba = new Uint8Array(4);
    var out = [];
    for (var dy = -1; dy <= 1; ++dy)
      for (var dx = -1; dx <= 1; ++dx) {
        var px = Math.round((x - L.left) * ratio) + dx, py = gl.drawingBufferHeight - 1 - Math.round((y - L.top) * ratio) - dy;
        gl.readPixels(px, py, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
        out.push('#' + new THREE.Color(rgba[0] / 255, rgba[1] / 255, rgba[2] / 255).getHexString());
      }
    return out;
  }
  function numbers(text) { return text ? text.split(',').map(Number).filter(function (x) { return isFinite(x); }) : []; }
  function selfTest() {
    var params = hashParams(), probes = [];
    var probeBodies = params.probe ? numbers(params.probe) : data.bodies.map(function (b, i) { return i; })
        .filter(function (i) { return data.bodies[i].moving_index >= 0; }).slice(0, 4);
    var probeFrames = params.probe_frames ? numbers(params.probe_frames) : [state.frame];
    var probeSize = params.probe_size ? numbers(params.probe_size.replace('x', ',')) : null;   // "800x600": a screenshot's window
    if (three.renderer)
      probeFrames.forEach(function (f) {
        probeBodies.forEach(function (b) {
          views.forEach(function (view, v) {
            var p = project(b, v, f, probeSize), out = { frame: f, body: b, view: v, x: p.x, y: p.y, colour: colourOf(b, v, f) };
            if (f === state.frame && !probeSize) out.pixels = drawnPixels(p.x, p.y);
            probes.push(out);
          });
        });
      });
    var runsPerBackend = {};
    data.runs.forEach(function (r) { runsPerBackend[r.backend] = (runsPerBackend[r.backend] || 0) + 1; });
    return {
      ok: window.vrocErrors.length === 0 && !!three.renderer, bodies: data.bodies.length, moving_bodies: data.moving_bodies,
      frames: data.times.length, recorded_frames: data.recorded_frames, stride: data.stride, runs: data.runs.length,
      backends: Object.keys(runsPerBackend), views: views.map(function (v) { return v.label; }), overlay: state.overlay,
      engines: views.map(function (v) { return { label: v.label, tint: v.tint }; }),
      legend: three.renderer ? drawnEntries('vroc-legend') : [], labels: three.renderer ? drawnEntries('vroc-labels') : [],
      frame: state.frame, time: data.times[state.frame], errors: window.vrocErrors.slice(),
      resources: performance.getEntriesByType('resource').length, notes: data.notes,
      load_ms: Math.round(performance.now()), probes: probes,
      timing: Object.keys(timing).reduce(function (o, k) { o[k] = Math.round(timing[k]); return o; }, {}),
      stage: (function () { var r = document.getElementById('vroc-stage').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; })(),
      window: [window.innerWidth, window.innerHeight],
      camera: three.camera ? { position: three.camera.position.toArray(), target: three.controls.target.toArray() } : null
    };
  }

  // ---- start ------------------------------------------------------------------------------------
  function controlsFromHash() {
    var p = hashParams();
    if (p.overlay) state.overlay = p.overlay === '1';
    if (p.colour) state.colour = p.colour;
    if (p.members) state.members = p.members === '1';
    if (p.events) state.events = p.events === '1';
    if (p.penetration) state.penetration = p.penetration === '1';
    if (p.ref) views.forEach(function (v, i) { if (v.label === p.ref) state.reference = i; });
    if (p.frame !== undefined) state.frame = Math.max(0, Math.min(data.times.length - 1, Number(p.frame) || 0));
    if (p.t !== undefined) state.frame = frameAtTime(Number(p.t) || 0);
  }
  function wireControls() {
    var $ = function (id) { return document.getElementById(id); };
    $('vroc-title').textContent = data.title;
    $('vroc-slider').max = data.times.length - 1;
    $('vroc-slider').addEventListener('input', function (e) { setPlaying(false); setFrame(Number(e.target.value)); });
    $('vroc-play').addEventListener('click', function () { setPlaying(!state.playing); });
    $('vroc-step').addEventListener('click', function () { setPlaying(false); setFrame(state.frame + 1); });
    $('vroc-step-back').addEventListener('click', function () { setPlaying(false); setFrame(state.frame - 1); });
    $('vroc-speed').addEventListener('change', function (e) { state.speed = Number(e.target.value); });
    $('vroc-overlay').checked = state.overlay;
    $('vroc-overlay').addEventListener('change', function (e) { state.overlay = e.target.checked; legend(); render(); });
    $('vroc-colour').value = state.colour;
    $('vroc-colour').addEventListener('change', function (e) { state.colour = e.target.value; legend(); render(); });
    views.forEach(function (v, i) {
      var o = document.createElement('option');
      o.value = i;
      o.textContent = v.label;
      $('vroc-reference').appendChild(o);
    });
    $('vroc-reference').value = state.reference;
    $('vroc-reference').addEventListener('change', function (e) { state.reference = Number(e.target.value); legend(); render(); });
    ['events', 'penetration', 'members'].forEach(function (name) {
      $('vroc-' + name).checked = state[name];
      $('vroc-' + name).addEventListener('change', function (e) { state[name] = e.target.checked; render(); });
    });
    window.addEventListener('keydown', function (e) {
      if (e.key === ' ') { setPlaying(!state.playing); e.preventDefault(); }
      if (e.key === 'ArrowRight') setFrame(state.frame + 1);
      if (e.key === 'ArrowLeft') setFrame(state.frame - 1);
    });
    window.addEventListener('resize', render);
    $('vroc-notes').textContent = data.notes.join(' \u2022 ');
    if (!views.some(function (v) { return v.members.length > 0; })) $('vroc-members').parentNode.hidden = true;
  }
  // A view's name after a swatch of its engine's tint: in the views' labels and the legend.
  function engineEntry(v) {
    var entry = document.createElement('span'), swatch = document.createElement('span');
    entry.className = 'vroc-engine';
    swatch.className = 'vroc-swatch';
    swatch.style.background = v.tint;
    entry.appendChild(swatch);
    entry.appendChild(document.createTextNode(v.label));
    return entry;
  }
  function legend() {
    var box = document.getElementById('vroc-legend');
    box.innerHTML = '';
    views.forEach(function (v) { box.appendChild(engineEntry(v)); });
    var text = (ghosts() && state.colour !== 'distance' ? 'ghosts in their engine\'s tint \u2022 ' : '') +
               'real: wireframe \u2022 virtual: shaded \u2022 tracked: orange edges \u2022 contacts: yellow \u2022 red glow: penetration deeper than ' +
               (1000 * data.collision_distance).toPrecision(2) + ' mm';
    if (state.colour === 'distance')
      text += ' \u2022 colour: distance from ' + views[state.reference].label + ', blue \u2264 ' +
              (1000 * data.collision_distance).toPrecision(2) + ' mm \u2026 red \u2265 1 m (log)';
    box.appendChild(document.createTextNode(text));
  }
  function start() {
    var canvas = document.getElementById('vroc-canvas');
    three.renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
    three.renderer.setPixelRatio(window.devicePixelRatio || 1);
    three.renderer.autoClear = false;
    three.scene = new THREE.Scene();
    three.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    three.camera.up.set(0, 0, 1);   // the scenes are Z-up
    three.scene.add(new THREE.AmbientLight(0xffffff, 0.5));
    var headlight = new THREE.DirectionalLight(0xffffff, 0.5);
    headlight.position.set(0, 0, 1);
    three.camera.add(headlight);
    three.scene.add(three.camera);
    three.controls = new THREE.OrbitControls(three.camera, canvas);
    three.controls.addEventListener('change', function () { if (!state.playing) render(); });
    buildStatic();
    buildViews();
    data.runs.forEach(function (d, r) { runs.push(buildRun(r)); });
    timing.built_ms = performance.now();
    controlsFromHash();
    fitCamera();
    wireControls();
    legend();
    render();
    timing.drawn_ms = performance.now();
  }

  window.vrocViewer = {
    selfTest: selfTest,
    setFrame: setFrame,
    setTime: function (t) { return setFrame(frameAtTime(t)); },
    setOverlay: function (on) { state.overlay = !!on; legend(); render(); },
    project: project,
    colourOf: colourOf,
    render: function () { render(); }
  };
  try {
    start();
  } catch (err) {
    window.vrocErrors.push('viewer: ' + (err && err.stack ? err.stack : err));
    var box = document.getElementById('vroc-error');
    box.hidden = false;
    box.textContent = 'The viewer could not start: ' + err;
  }
  // Written into the page so headless Chromium's --dump-dom shows it.
  document.getElementById('vroc-selftest').textContent = JSON.stringify(selfTest());
})();
