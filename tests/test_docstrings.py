"""Every class has a docstring from its C++ declaration (classDoc) followed by its attributes with
their default values and descriptions; help() shows them."""
import pydoc

import yade
from yade import system


def _classes():
    names = sorted(system._allSerializables())
    assert len(names) > 50
    return [(n, getattr(yade.wrapper, n)) for n in names]


def test_every_class_has_its_own_description():
    missing = [n for n, c in _classes() if not c.__doc__ or c.__doc__.startswith('(no class description)')]
    assert missing == [], 'classes without a classDoc: %s' % missing


def test_doc_names_every_attribute_with_its_default():
    for name, cls in _classes():
        obj = cls()
        for attr in obj.dict():
            assert ('    %s = ' % attr) in cls.__doc__, (name, attr)
            # (the class's own attribute object: a class-wide one, Gl1_Sphere.quality, reads as its value)
            assert attr not in cls.__dict__ or 'default: ' in cls.__dict__[attr].__doc__, (name, attr)


def test_sphere_doc_and_help():
    doc = yade.Sphere.__doc__
    assert doc.startswith('Geometry of a spherical particle')
    assert '    radius = nan\n        Radius' in doc
    assert 'inherited from Shape:' in doc and '    color = Vector3(1,1,1)' in doc
    assert yade.Sphere.radius.__doc__.endswith('[default: nan]')
    text = pydoc.render_doc(yade.Sphere, renderer=pydoc.plaintext)
    assert 'class Sphere in module yade.wrapper' in text
    assert 'radius' in text and '[default: nan]' in text


def test_classdoc_is_not_inherited():
    # FrictMat's own description, not ElastMat's or Material's
    assert yade.FrictMat.__doc__.startswith('Elastic material with Coulomb contact friction')
    assert yade.ElastMat.__doc__.split('\n')[0] != yade.FrictMat.__doc__.split('\n')[0]
    assert 'Derives from ElastMat.' in yade.FrictMat.__doc__
    # pointer attributes show the class of their default object, not an address
    assert '    state = State()' in yade.Body.__doc__
