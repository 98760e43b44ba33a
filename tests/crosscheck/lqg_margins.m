% Cross-check of the run-to-run LQG loop margins (core/control/margins.cpp) with Octave's control
% package (Debian bookworm: octave 7.3.0, octave-control 3.4.0). Input: the JSON of
% `trueturn lqg --delay z --json` (plant A, B, C and the gains K, L), so only the design is shared with
% the product, not the margin code. Loop of point 1 (the points are decoupled by the diagonal weights),
% negative feedback convention L = -K(z) P(z).
%  - gain margin and its frequency: `margin` (exact);
%  - every gain crossover with its phase margin, the |S| peak and the balanced disk margin
%    alpha = 1 / max|S - 1/2| (MATLAB `diskmargin`, sigma = 0): `freqresp` on 200001 frequencies in
%    [0.001, pi] (Octave's `norm(S, inf)` stops at 2.086 where the response reaches 2.0879 at z = 2).
% Install: scripts/install-deps.sh --with-crosscheck-tools. Usage: octave --no-gui --eval "lqg_margins('lqg_z1.json')"
function lqg_margins(file)
  pkg load control
  d = jsondecode(fileread(file));
  A = d.plant.A; B = d.plant.B; C = d.plant.C; K = d.lq.K; L = d.kalman.L;
  n = rows(A);
  Ac = (A - B*K) * (eye(n) - L*C); Bc = (A - B*K) * L; Cc = -K * (eye(n) - L*C); Dc = -K * L;
  P = ss(A, B, C, zeros(rows(C), columns(B)), 1);
  Kc = ss(Ac, Bc, Cc, Dc, 1);
  T = Kc * P;
  Lp = -T(1, 1);
  [gm, ~, wpc] = margin(Lp);
  w = linspace(0.001, pi, 200001);
  h = squeeze(freqresp(Lp, w));
  s = 1 ./ (1 + h);
  printf('delay %d: gain margin %.6f at %.6f rad/part; |S| peak %.6f; disk alpha %.6f\n', ...
         d.delay, gm, wpc, max(abs(s)), 1 / max(abs(s - 0.5)));
  idx = find(diff(sign(abs(h) - 1)));
  for j = idx(:)'
    pm = mod(angle(h(j)) * 180 / pi + 180 + 180, 360) - 180;
    printf('  gain crossover %.5f rad/part: phase margin %.3f deg, delay margin %.4f parts\n', ...
           w(j), pm, mod(pm, 360) * pi / 180 / w(j));
  end
end
