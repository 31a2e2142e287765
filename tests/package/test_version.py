import screwsym


def test_version():
    assert screwsym.__version__ == "0.1.0"
