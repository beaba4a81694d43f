#include "harness/outputs/viewer/viewer_script.h"

namespace holebench::viewer {

const char* viewer_script() {
  return R"JS(// holebench report: the 3D viewer. three.js r111 (global THREE), OrbitControls.
(function () {
  'use strict';
  var config = JSON.parse(document.getElementById('viewer-config').textContent);
  var cases = JSON.parse(document.getElementById('viewer-cases').textContent);
  var select = document.getElementById('viewer-case');
  var toggles = document.getElementById('viewer-toggles');
  var status = document.getElementById('viewer-status');
  var canvas = document.getElementById('viewer-canvas');
  var bar = document.getElementById('viewer-bar');
  var wholeButton = document.getElementById('viewer-whole');
  var payloads = {};   // file name -> base64 of its gzip PLY (meshes/*.js)
  var requested = {};  // file name -> its <script> element was added
  var parsed = {};     // case index -> {name: parsed PLY, a job's assembled}
  var parsing = {};    // case index -> its files are being decompressed
  var shown = {};      // case index -> {name: ticked}
  var whole = {};      // case index -> true: the whole models, false: the first hole close up
  var current = -1;
  var followHash = window.location.hash === '#viewer';
  var three = null;    // {renderer, scene, camera, controls, group}

  function say(text) { status.textContent = text; }

  // A viewer file's payload: base64 of a gzip stream, decompressed by the browser.
  function decode(base64) {
    var binary = window.atob(base64);
    var bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
    return new Response(stream).arrayBuffer();
  }

  function baseName(file) { return file.split('/').pop(); }

  // The viewer meshes' PLY (harness/outputs/viewer/viewer_mesh.h).
  function parsePly(buffer) {
    var bytes = new Uint8Array(buffer);
    var text = '';
    var headerEnd = -1;
    for (var i = 0; i < Math.min(bytes.length, 8192); ++i) {
      text += String.fromCharCode(bytes[i]);
      if (bytes[i] === 10 && text.slice(-11) === 'end_header\n') { headerEnd = i + 1; break; }
    }
    if (headerEnd < 0 || text.indexOf('binary_little_endian') < 0) throw new Error('not a viewer PLY');
    var counts = {vertex: 0, face: 0, edge: 0};
    var split = text.indexOf('property uchar splits') >= 0;  // a job's patch file
    var scale = 0;
    var direction = null, target = null, distance = 0, fieldOfView = 40;
    text.split('\n').forEach(function (line) {
      var w = line.trim().split(/\s+/);
      if (w[0] === 'element') counts[w[1]] = parseInt(w[2], 10);
      if (w[0] === 'comment' && w[1] === 'heat_scale_max_rel_diag') scale = parseFloat(w[2]);
      if (w[0] === 'comment' && w[1] === 'view_direction') {
        direction = [parseFloat(w[2]), parseFloat(w[3]), parseFloat(w[4])];
      }
      if (w[0] === 'comment' && w[1] === 'view_target') {
        target = [parseFloat(w[2]), parseFloat(w[3]), parseFloat(w[4])];
      }
      if (w[0] === 'comment' && w[1] === 'view_distance') distance = parseFloat(w[2]);
      if (w[0] === 'comment' && w[1] === 'view_field_of_view_degrees') fieldOfView = parseFloat(w[2]);
    });
    var view = new DataView(buffer, headerEnd);
    var at = 0;
    var positions = new Float32Array(counts.vertex * 3);
    var quality = new Float32Array(counts.vertex);
    for (var v = 0; v < counts.vertex; ++v, at += 16) {
      positions[3 * v] = view.getFloat32(at, true);
      positions[3 * v + 1] = view.getFloat32(at + 4, true);
      positions[3 * v + 2] = view.getFloat32(at + 8, true);
      quality[v] = view.getFloat32(at + 12, true);
    }
    var faces = new Int32Array(counts.face * 3);
    var patch = new Uint8Array(counts.face);
    var splits = [];  // by face of a patch file: {n, quality} or null
    for (var f = 0; f < counts.face; ++f) {
      if (view.getUint8(at) !== 3) throw new Error('a face that is not a triangle');
      faces[3 * f] = view.getInt32(at + 1, true);
      faces[3 * f + 1] = view.getInt32(at + 5, true);
      faces[3 * f + 2] = view.getInt32(at + 9, true);
      patch[f] = view.getUint8(at + 13);
      at += 14;
      if (!split) continue;
      var n = view.getUint8(at);
      var m = view.getUint8(at + 1);
      at += 2;
      var q = new Float32Array(m);
      for (var k = 0; k < m; ++k, at += 4) q[k] = view.getFloat32(at, true);
      splits.push(n > 0 ? {n: n, quality: q} : null);
    }
    var edges = new Int32Array(counts.edge * 2);
    for (var e = 0; e < counts.edge; ++e, at += 8) {
      edges[2 * e] = view.getInt32(at, true);
      edges[2 * e + 1] = view.getInt32(at + 4, true);
    }
    at += 8 * (counts.sewn_vertex || 0);  // where the patch is sewn: not needed to draw it
    var dropped = new Int32Array(counts.dropped_face || 0);
    for (var d = 0; d < dropped.length; ++d, at += 4) dropped[d] = view.getInt32(at, true);
    var ply = {positions: positions, quality: quality, faces: faces, patch: patch, edges: edges,
               dropped: dropped, scale: scale, direction: direction, target: target,
               distance: distance, fieldOfView: fieldOfView};
    return split ? splitFaces(ply, splits) : ply;
  }

  // The patch file's new faces split into n x n pieces, each piece's corners with their own
  // distances (viewer_mesh.h: vertex (i, j) at c0 + (i (c1 - c0) + j (c2 - c0)) / n).
  function splitFaces(ply, splits) {
    var positions = Array.prototype.slice.call(ply.positions);
    var quality = Array.prototype.slice.call(ply.quality);
    var faces = [];
    var patch = [];
    var count = ply.faces.length / 3;
    for (var f = 0; f < count; ++f) {
      var s = splits[f];
      var corner = [ply.faces[3 * f], ply.faces[3 * f + 1], ply.faces[3 * f + 2]];
      if (!s) {
        faces.push(corner[0], corner[1], corner[2]);
        patch.push(ply.patch[f]);
        continue;
      }
      var n = s.n;
      var first = quality.length;
      var c = corner.map(function (v) {
        return [ply.positions[3 * v], ply.positions[3 * v + 1], ply.positions[3 * v + 2]];
      });
      var at = 0;
      for (var j = 0; j <= n; ++j) {
        for (var i = 0; i + j <= n; ++i, ++at) {
          for (var d = 0; d < 3; ++d) {
            positions.push(c[0][d] + (i * (c[1][d] - c[0][d]) + j * (c[2][d] - c[0][d])) / n);
          }
          quality.push(s.quality[at]);
        }
      }
      var index = function (i, j) { return first + j * (n + 1) - j * (j - 1) / 2 + i; };
      for (var jj = 0; jj < n; ++jj) {
        for (var ii = 0; ii + jj < n; ++ii) {
          faces.push(index(ii, jj), index(ii + 1, jj), index(ii, jj + 1));
          patch.push(ply.patch[f]);
          if (ii + jj + 1 < n) {
            faces.push(index(ii + 1, jj), index(ii + 1, jj + 1), index(ii, jj + 1));
            patch.push(ply.patch[f]);
          }
        }
      }
    }
    ply.positions = new Float32Array(positions);
    ply.quality = new Float32Array(quality);
    ply.faces = new Int32Array(faces);
    ply.patch = new Uint8Array(patch);
    return ply;
  }

  // A job's repaired mesh: the holed mesh without the faces the repair dropped, and the
  // patch (its faces and the repaired mesh's open edges), as viewer_mesh.h writes them.
  function assemble(holed, patch) {
    var base = holed.positions.length / 3;
    var drop = new Uint8Array(holed.faces.length / 3);
    for (var d = 0; d < patch.dropped.length; ++d) drop[patch.dropped[d]] = 1;
    var keptCount = drop.length - patch.dropped.length;
    var patchCount = patch.faces.length / 3;
    var positions = new Float32Array(holed.positions.length + patch.positions.length);
    positions.set(holed.positions);
    positions.set(patch.positions, holed.positions.length);
    var quality = new Float32Array(base + patch.quality.length);
    quality.set(patch.quality, base);
    var faces = new Int32Array(3 * (keptCount + patchCount));
    var flags = new Uint8Array(keptCount + patchCount);
    var at = 0;
    for (var f = 0; f < drop.length; ++f) {
      if (drop[f]) continue;
      faces.set(holed.faces.subarray(3 * f, 3 * f + 3), 3 * at);
      ++at;
    }
    for (var g = 0; g < patchCount; ++g, ++at) {
      for (var k = 0; k < 3; ++k) faces[3 * at + k] = base + patch.faces[3 * g + k];
      flags[at] = patch.patch[g];
    }
    var edges = new Int32Array(patch.edges.length);
    for (var e = 0; e < edges.length; ++e) edges[e] = base + patch.edges[e];
    return {positions: positions, quality: quality, faces: faces, patch: flags, edges: edges,
            dropped: new Int32Array(0), scale: patch.scale, direction: holed.direction,
            target: holed.target, distance: holed.distance, fieldOfView: holed.fieldOfView};
  }

  // Decompresses and parses the case's files (all received), then shows the case.
  function prepare(index) {
    if (parsing[index]) return;
    parsing[index] = true;
    var c = cases[index];
    Promise.all(c.files.map(function (file) { return decode(payloads[baseName(file)]); }))
      .then(function (buffers) {
        var plies = buffers.map(parsePly);
        var holed = plies[c.meshes.indexOf('holed')];
        var out = {};
        c.meshes.forEach(function (name, i) {
          out[name] = c.patch[i] ? assemble(holed, plies[i]) : plies[i];
        });
        parsed[index] = out;
        if (index === current) show();
      })
      .catch(function (e) { parsing[index] = false; say('error: ' + e.message); });
  }

  function received(index) {
    return cases[index].files.every(function (file) { return payloads[baseName(file)] !== undefined; });
  }

  function gamma(c) { return [Math.pow(c[0], 1 / 2.2), Math.pow(c[1], 1 / 2.2), Math.pow(c[2], 1 / 2.2)]; }

  // The pictures' heat map (render/heat_map.h): linear between the stops, clamped at the top.
  function heat(t) {
    var s = config.stops;
    t = Math.max(0, Math.min(1, t));
    if (t >= 1) return s[s.length - 1];
    var p = t * (s.length - 1);
    var i = Math.min(Math.floor(p), s.length - 2);
    var f = p - i;
    return [0, 1, 2].map(function (k) { return s[i][k] + (s[i + 1][k] - s[i][k]) * f; });
  }

  function setAttribute(geometry, name, attribute) {
    if (geometry.setAttribute) geometry.setAttribute(name, attribute);
    else geometry.addAttribute(name, attribute);
  }

  // One mesh as a three.js object: flat-shaded triangles (kept faces grey, the patch by its
  // distance on the case's scale) and the open boundary edges; `clipping`: planes that cut
  // away what lies outside the mesh's window (the close-up), or none.
  function buildObject(ply, scaleMax, clipping) {
    var count = ply.faces.length / 3;
    var positions = new Float32Array(count * 9);
    var colours = new Float32Array(count * 9);
    var kept = gamma(config.kept);
    for (var f = 0; f < count; ++f) {
      for (var k = 0; k < 3; ++k) {
        var v = ply.faces[3 * f + k];
        var c = ply.patch[f] ? gamma(heat(ply.quality[v] / scaleMax)) : kept;
        for (var d = 0; d < 3; ++d) {
          positions[9 * f + 3 * k + d] = ply.positions[3 * v + d];
          colours[9 * f + 3 * k + d] = c[d];
        }
      }
    }
    var geometry = new THREE.BufferGeometry();
    setAttribute(geometry, 'position', new THREE.BufferAttribute(positions, 3));
    setAttribute(geometry, 'color', new THREE.BufferAttribute(colours, 3));
    geometry.computeVertexNormals();
    var material = new THREE.MeshLambertMaterial({vertexColors: THREE.VertexColors,
                                                  side: THREE.DoubleSide,
                                                  clippingPlanes: clipping});
    var object = new THREE.Group();
    object.add(new THREE.Mesh(geometry, material));
    if (ply.edges.length > 0) {
      var points = new Float32Array(ply.edges.length * 3);
      for (var i = 0; i < ply.edges.length; ++i) {
        for (var j = 0; j < 3; ++j) points[3 * i + j] = ply.positions[3 * ply.edges[i] + j];
      }
      var lines = new THREE.BufferGeometry();
      setAttribute(lines, 'position', new THREE.BufferAttribute(points, 3));
      var open = gamma(config.open);
      object.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial(
          {color: new THREE.Color(open[0], open[1], open[2]), clippingPlanes: clipping})));
    }
    return object;
  }

  function initThree() {
    if (three) return three;
    var renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true,
                                            preserveDrawingBuffer: true});
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
    renderer.setClearColor(new THREE.Color(config.background), 1);
    renderer.localClippingEnabled = true;  // the close-up's windows
    var scene = new THREE.Scene();
    var camera = new THREE.PerspectiveCamera(40, canvas.clientWidth / canvas.clientHeight, 0.01, 100);
    camera.up.set(0, 0, 1);  // the models' z is up
    scene.add(new THREE.AmbientLight(0xffffff, 0.45));
    var light = new THREE.DirectionalLight(0xffffff, 0.6);
    light.position.set(0, 0, 1);
    camera.add(light);  // a headlight
    scene.add(camera);
    var controls = new THREE.OrbitControls(camera, canvas);
    var group = new THREE.Group();
    scene.add(group);
    three = {renderer: renderer, scene: scene, camera: camera, controls: controls, group: group};
    controls.addEventListener('change', draw);
    canvas.addEventListener('pointerdown', function () { followHash = false; });
    return three;
  }

  function draw() {
    three.renderer.render(three.scene, three.camera);
    if (followHash) canvas.scrollIntoView();
  }

  function drawBar(scaleMax) {
    var stops = config.stops.map(function (c) {
      var g = gamma(c);
      return 'rgb(' + g.map(function (x) { return Math.round(255 * x); }).join(',') + ')';
    });
    bar.innerHTML = '';
    var strip = document.createElement('div');
    strip.className = 'viewer-strip';
    strip.style.background = 'linear-gradient(to top, ' + stops.join(', ') + ')';
    bar.appendChild(strip);
    [scaleMax, scaleMax / 2, 0].forEach(function (value, i) {
      var label = document.createElement('span');
      label.className = 'viewer-label viewer-label-' + i;
      label.textContent = value === 0 ? '0' : Number(value.toPrecision(2)).toString();
      bar.appendChild(label);
    });
  }

  // The ticked meshes of the current case, side by side in the order of the list, in rows.
  function show() {
    var index = current;
    var meshes = cases[index].meshes;
    var t = initThree();
    while (t.group.children.length > 0) {
      var old = t.group.children[0];
      t.group.remove(old);
      old.traverse(function (o) { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    }
    var ticked = meshes.filter(function (name) { return shown[index][name]; });
    var scaleMax = 0;
    meshes.forEach(function (name) { scaleMax = Math.max(scaleMax, parsed[index][name].scale); });
    if (scaleMax <= 0) scaleMax = 0.01;
    drawBar(scaleMax);
    // The camera looks along the first hole's close-up direction (from the ground truth);
    // the meshes stand side by side across the view, in rows.
    var d = parsed[index][meshes[0]].direction || [-0.55, 0.75, -0.45];
    var direction = new THREE.Vector3(d[0], d[1], d[2]).normalize();
    // z stays up (the orbit's axis): a view straight down or up is tilted a little.
    if (Math.abs(direction.z) > 0.95) direction.add(new THREE.Vector3(0.35, -0.3, 0)).normalize();
    var up = new THREE.Vector3(0, 0, 1);
    var right = new THREE.Vector3().crossVectors(direction, up).normalize();
    var screenUp = new THREE.Vector3().crossVectors(right, direction).normalize();
    var first = parsed[index][meshes[0]];
    var atHole = !whole[index] && first.target !== null && first.distance > 0;
    // The close-up's field of view (the snapshot's camera), the viewer camera's too.
    t.camera.fov = first.fieldOfView;
    var halfAngle = first.fieldOfView / 2 * Math.PI / 180;
    var halfAngleTan = Math.tan(halfAngle);
    if (wholeButton) {
      wholeButton.textContent = atHole ? 'whole model' : 'the hole';
      wholeButton.disabled = first.target === null || !(first.distance > 0);
    }
    var columns = Math.max(1, Math.ceil(Math.sqrt(ticked.length)));
    var rows = Math.max(1, Math.ceil(ticked.length / columns));
    var centre, reach;
    if (atHole) {
      // Each mesh in a window around the first hole, as the close-up snapshot frames it
      // (the hole's boundary over about two thirds of the view), cut by clipping planes so
      // that the windows stand side by side at the same scale.
      centre = new THREE.Vector3(first.target[0], first.target[1], first.target[2]);
      reach = 0.85 * first.distance * halfAngleTan;
    } else {
      var box = new THREE.Box3();
      box.setFromArray(first.positions);
      var one = box.getBoundingSphere(new THREE.Sphere());
      centre = one.center;
      reach = one.radius;
    }
    var step = (atHole ? 2.05 : 2.2) * reach;
    ticked.forEach(function (name, i) {
      var column = i % columns - (columns - 1) / 2;
      var row = Math.floor(i / columns) - (rows - 1) / 2;
      var offset = right.clone().multiplyScalar(column * step).addScaledVector(screenUp, -row * step);
      var clipping = [];
      if (atHole) {
        var c = centre.clone().add(offset);
        [right, screenUp].forEach(function (axis) {
          clipping.push(new THREE.Plane(axis.clone(), reach - axis.dot(c)));
          clipping.push(new THREE.Plane(axis.clone().negate(), reach + axis.dot(c)));
        });
      }
      var object = buildObject(parsed[index][name], scaleMax, clipping);
      object.position.copy(offset);
      t.group.add(object);
    });
    var across = Math.max(columns, rows);
    // At the hole: the rows and columns of windows fill the canvas (its aspect) with a small
    // margin; whole: the old framing, the arrangement's bounding sphere in view.
    var aspect = canvas.clientWidth / Math.max(1, canvas.clientHeight);
    var halfHeight = 0.5 * step * Math.max(rows, columns / aspect);
    var distance = atHole ? 1.05 * halfHeight / halfAngleTan
                          : 1.1 * reach * across * 1.15 / Math.sin(halfAngle);
    var sphere = new THREE.Sphere(centre.clone(), reach * across);
    t.camera.position.copy(sphere.center).addScaledVector(direction, -distance);
    t.camera.near = distance / 100;
    t.camera.far = distance * 10;
    t.camera.updateProjectionMatrix();
    t.controls.target.copy(sphere.center);
    t.controls.update();
    draw();
    say((atHole ? 'the first hole close up: ' : 'the whole model: ') + 'showing ' +
        ticked.length + ' of ' + meshes.length + ' meshes' +
        (ticked.length > 1 ? ', left to right and row by row: ' + ticked.join(', ') : '') + '.');
  }

  function buildToggles(index) {
    toggles.innerHTML = '';
    cases[index].meshes.forEach(function (name) {
      var label = document.createElement('label');
      var box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = shown[index][name];
      box.addEventListener('change', function () { shown[index][name] = box.checked; show(); });
      label.appendChild(box);
      label.appendChild(document.createTextNode(' ' + name + ' '));
      toggles.appendChild(label);
    });
  }

  function choose(index) {
    current = index;
    if (!shown[index]) {
      shown[index] = {};
      cases[index].meshes.forEach(function (name) {
        shown[index][name] = name !== 'complete' && name !== 'holed';
      });
    }
    buildToggles(index);
    if (parsed[index]) { show(); return; }
    say('loading ' + cases[index].id + ' ...');
    if (received(index)) { prepare(index); return; }
    cases[index].files.forEach(function (file) {
      if (requested[baseName(file)]) return;
      requested[baseName(file)] = true;
      var script = document.createElement('script');
      script.src = file;
      script.onerror = function () { say('error: cannot load ' + file); };
      document.head.appendChild(script);
    });
  }

  window.holebenchViewer = {
    receiveMesh: function (name, payload) {
      payloads[name] = payload;
      if (current >= 0 && received(current)) prepare(current);
    }
  };

  if (typeof THREE === 'undefined' || typeof THREE.OrbitControls === 'undefined') {
    say('error: three.js did not load (viewer/three.min.js, viewer/OrbitControls.js)');
    return;
  }
  try { initThree(); } catch (e) { say('error: no WebGL here (' + e.message + ')'); return; }
  cases.forEach(function (c, i) {
    var option = document.createElement('option');
    option.value = String(i);
    option.textContent = c.id;
    select.appendChild(option);
  });
  select.addEventListener('change', function () { choose(parseInt(select.value, 10)); });
  if (wholeButton) {
    wholeButton.addEventListener('click', function () {
      if (current < 0 || !parsed[current]) return;
      whole[current] = !whole[current];
      show();
    });
  }
  if (cases.length > 0) choose(0);
  else say('no case has viewer meshes (run with snapshots)');
})();
)JS";
}

}  // namespace holebench::viewer
