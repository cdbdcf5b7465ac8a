"""Chapter 10 with numpy: 4x4 arrays, @ for products and for a homogeneous point.
Written for the checker's corpus (tests/check-functions/check_corpus.mjs); checked
where a python3 has numpy."""
import numpy as np


def MakeTranslationMatrix(translation):
    M = np.identity(4)
    M[:3, 3] = translation
    return M


def MakeScalingMatrix(scale):
    return np.diag([scale, scale, scale, 1.0])


def MakeOYRotationMatrix(degrees):
    a = np.radians(degrees)
    return np.array([[np.cos(a), 0, -np.sin(a), 0], [0, 1, 0, 0], [np.sin(a), 0, np.cos(a), 0], [0, 0, 0, 1]])


def ApplyTransform(vertex, transform):
    point = np.append(np.asarray(vertex, dtype=float) * transform.scale, 1.0)
    moved = np.asarray(transform.rotation) @ point
    return moved[:3] + np.asarray(transform.translation)


def MakeCameraMatrix(position, orientation):
    return np.asarray(orientation).T @ MakeTranslationMatrix(-np.asarray(position, dtype=float))
