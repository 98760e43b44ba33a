#!/usr/bin/python3
"""Reference values for the prediction variance of a least-squares fit and its sequential design
(tests/core/model/optimal_design_test.cpp), computed with statsmodels' OLS.

  scripts/crosscheck-design.py

Prints, for a fixed design in two coded factors (f, z in [-1, 1]; terms 1, f, z, f*z, f^2, z^2) and
fixed responses:
  - the OLS coefficients, the residual sigma and, at three prediction rows, se_mean (the standard error of
    the fitted mean) and the 95 % confidence half width t(0.975; n-p) * se_mean
    (OLSResults.get_prediction(...).se_mean, .conf_int());
  - the variance factors x'(X'X)^-1 x = se_mean^2 / scale at the prediction rows, before and after two
    more rows are measured (the design's Sherman-Morrison-Woodbury update must give the refit's value).
The test compares TrueTurn's LinearRegression::confidenceHalfWidth and PredictionVarianceDesign with these
numbers. Debian 12: python3-numpy, python3-statsmodels (scripts/install-deps.sh --with-test-tools).
"""

import numpy as np
import statsmodels.api as sm

F = [-1.0, -1.0, -1.0, -0.5, -0.5, 0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0]
Z = [-1.0, 0.0, 1.0, -0.5, 0.5, -1.0, 0.0, 1.0, -0.5, 0.5, -1.0, 0.0, 1.0]
Y = [3.1, 4.0, 5.2, 4.4, 5.3, 4.9, 5.6, 6.8, 6.1, 6.9, 6.5, 7.4, 8.9]
PREDICT = [(0.25, 0.75), (-0.8, 0.9), (1.0, -1.0)]
ADDED = [(0.25, 0.75), (-0.75, 1.0)]


def rows(points):
    return np.array([[1.0, f, z, f * z, f * f, z * z] for f, z in points])


def main():
    x = rows(list(zip(F, Z)))
    fit = sm.OLS(np.array(Y), x).fit()
    xp = rows(PREDICT)
    pred = fit.get_prediction(xp)
    ci = pred.conf_int(alpha=0.05)
    print("coefficients:", ", ".join("%.12g" % b for b in fit.params))
    print("residual sigma: %.12g" % np.sqrt(fit.scale))
    for k, (f, z) in enumerate(PREDICT):
        print("at f=%g z=%g: mean %.12g se_mean %.12g half width %.12g factor %.12g" %
              (f, z, pred.predicted_mean[k], pred.se_mean[k], (ci[k, 1] - ci[k, 0]) / 2,
               pred.se_mean[k] ** 2 / fit.scale))
    # The factors do not depend on y: refit with any responses on the augmented design.
    xa = np.vstack([x, rows(ADDED)])
    ya = np.concatenate([Y, [6.0, 5.0]])
    fa = sm.OLS(ya, xa).fit()
    after = fa.get_prediction(xp).se_mean ** 2 / fa.scale
    before = pred.se_mean ** 2 / fit.scale
    print("average factor before %.12g after %.12g reduction %.12g" %
          (before.mean(), after.mean(), before.mean() - after.mean()))
    print("factors after:", ", ".join("%.12g" % v for v in after))


if __name__ == "__main__":
    main()
